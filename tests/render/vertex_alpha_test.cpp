// Vertex alpha, as glTF's COLOR_0 alpha: it multiplies a blended or masked material's alpha and
// is ignored by an opaque one (doc/conventions.md#vertex-alpha).
#include <raster/image/colour.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include "support/picture.hpp"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>
#include <gtest/gtest.h>

namespace {

constexpr int kSize = 8;
const raster::Rgb kBlueBackground{0, 0, 255};

// An unlit red square facing the camera from -half to +half in x and y (the view spans -1..1),
// its corners' alphas at (-, -), (+, -), (+, +), (-, +).
raster::SceneObject red_square(float half, std::vector<float> alphas, raster::Opacity opacity) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions = {{-half, -half, 0.0F}, {half, -half, 0.0F}, {half, half, 0.0F}, {-half, half, 0.0F}};
    mesh->normals.assign(4, {0.0F, 0.0F, -1.0F});
    mesh->alphas = std::move(alphas);
    const glm::vec3 behind(0.0F, 0.0F, 1.0F);
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    raster::SceneObject object{mesh, glm::mat4(1.0F), raster::LinearMaterial{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {}},
                               raster::ShadingMethod::unlit};
    object.opacity = opacity;
    return object;
}

raster::Framebuffer drawn(raster::SceneObject object, int samples = 1) {
    raster::Scene scene{raster::OrthoCamera(kSize, kSize), kBlueBackground, {}, {}, {}};
    scene.objects = {std::move(object)};
    raster::Framebuffer image(kSize, kSize);
    raster::Renderer renderer({.threads = 1, .samples = samples});
    renderer.render(image, scene);
    return image;
}

raster::Rgb bytes_of(float r, float g, float b) {
    return {raster::srgb_byte_from_linear(r), raster::srgb_byte_from_linear(g), raster::srgb_byte_from_linear(b)};
}

const std::map<char, raster::Rgb> kLegend = {{'B', kBlueBackground}, {'r', {255, 0, 0}}};

}  // namespace

TEST(VertexAlpha, HalfAlphaInABlendMaterialBlendsOverTheBackgroundInLinearLight) {
    // Red at vertex alpha 0.5 over blue: half of each in linear light, where the square covers.
    std::map<char, raster::Rgb> legend = kLegend;
    legend['m'] = bytes_of(0.5F, 0.0F, 0.5F);
    const std::vector<std::string> half = {"BBBBBBBB", "BBBBBBBB", "BBmmmmBB", "BBmmmmBB",
                                           "BBmmmmBB", "BBmmmmBB", "BBBBBBBB", "BBBBBBBB"};
    EXPECT_TRUE(test_support::looks_like(
        drawn(red_square(0.5F, {0.5F, 0.5F, 0.5F, 0.5F}, {raster::AlphaMode::blend, 1.0F, 0.5F})), half, legend));
    // The factor multiplies it: 0.5 x 0.5 is a quarter of red.
    legend['q'] = bytes_of(0.25F, 0.0F, 0.75F);
    const std::vector<std::string> quarter = {"BBBBBBBB", "BBBBBBBB", "BBqqqqBB", "BBqqqqBB",
                                              "BBqqqqBB", "BBqqqqBB", "BBBBBBBB", "BBBBBBBB"};
    EXPECT_TRUE(test_support::looks_like(
        drawn(red_square(0.5F, {0.5F, 0.5F, 0.5F, 0.5F}, {raster::AlphaMode::blend, 0.5F, 0.5F})), quarter, legend));
}

TEST(VertexAlpha, AnOpaqueMaterialIgnoresIt) {
    const std::vector<std::string> whole = {"BBBBBBBB", "BBBBBBBB", "BBrrrrBB", "BBrrrrBB",
                                            "BBrrrrBB", "BBrrrrBB", "BBBBBBBB", "BBBBBBBB"};
    EXPECT_TRUE(test_support::looks_like(drawn(red_square(0.5F, {0.0F, 0.25F, 0.5F, 0.0F}, {})), whole, kLegend));
}

TEST(VertexAlpha, AMaskCutsWhereTheCornersAlphaFallsUnderTheCutoff) {
    // The square overfills the view, its alpha running from 0 at x = -2 to 1 at x = 2: 0.5 at the
    // middle column line, so the left half is cut and the right half drawn whole, at 1 and at 4 samples.
    const std::vector<std::string> right = {"BBBBrrrr", "BBBBrrrr", "BBBBrrrr", "BBBBrrrr",
                                            "BBBBrrrr", "BBBBrrrr", "BBBBrrrr", "BBBBrrrr"};
    const raster::Opacity mask{raster::AlphaMode::mask, 1.0F, 0.5F};
    EXPECT_TRUE(test_support::looks_like(drawn(red_square(2.0F, {0.0F, 1.0F, 1.0F, 0.0F}, mask)), right, kLegend));
    EXPECT_TRUE(test_support::looks_like(drawn(red_square(2.0F, {0.0F, 1.0F, 1.0F, 0.0F}, mask), 4), right, kLegend));
    // A factor under the cutoff hides it all, whatever the corners say.
    const std::vector<std::string> none(kSize, std::string(kSize, 'B'));
    EXPECT_TRUE(test_support::looks_like(
        drawn(red_square(2.0F, {1.0F, 1.0F, 1.0F, 1.0F}, {raster::AlphaMode::mask, 0.4F, 0.5F})), none, kLegend));
}

TEST(VertexAlpha, AMeshWithoutAlphasDrawsAsBefore) {
    // An empty alpha array is every corner opaque: a blended square of factor 1 covers the blue whole.
    const std::vector<std::string> whole = {"BBBBBBBB", "BBBBBBBB", "BBrrrrBB", "BBrrrrBB",
                                            "BBrrrrBB", "BBrrrrBB", "BBBBBBBB", "BBBBBBBB"};
    EXPECT_TRUE(
        test_support::looks_like(drawn(red_square(0.5F, {}, {raster::AlphaMode::blend, 1.0F, 0.5F})), whole, kLegend));
}

TEST(VertexAlpha, AnAlphaArrayOfAnotherLengthIsRefused) {
    EXPECT_THROW((void)drawn(red_square(0.5F, {0.5F, 0.5F}, {raster::AlphaMode::blend, 1.0F, 0.5F})),
                 std::invalid_argument);
}
