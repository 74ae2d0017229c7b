// glTF COLOR_0's alpha read as Mesh::alphas, carried from the reader process and drawn
// (doc/conventions.md#vertex-alpha).
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>

#include "support/gltf_square.hpp"
#include "support/scratch.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>
#include <gtest/gtest.h>

namespace {

const std::string kBlend = R"({"alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}})";

// The square of test_support::write_gltf_square, its corners coloured white with these alphas.
raster::Model square_with_alphas(const std::string& material, std::vector<float> alphas) {
    const test_support::ScratchDir dir;
    std::vector<float> rgba;
    for (const float a : alphas) rgba.insert(rgba.end(), {1.0F, 1.0F, 1.0F, a});
    return raster::read_model(
        test_support::write_gltf_square(dir.path(), material, "", R"([{"mesh": 0}])", false, rgba));
}

std::vector<float> sorted(std::vector<float> values) {
    std::sort(values.begin(), values.end());
    return values;
}

// How many pixels of the square's picture differ from the background (its first pixel, outside the square).
int pixels_shown(const raster::Model& model) {
    raster::Framebuffer image(32, 32);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const raster::Model>(model), {}, image.width(), image.height())
        .render(image, depth, 0.0, {.samples = 1});
    int shown = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) shown += image.pixel(x, y) == image.pixel(0, 0) ? 0 : 1;
    }
    return shown;
}

}  // namespace

TEST(GltfVertexAlpha, Color0AlphaIsReadOnePerVertexAndBlends) {
    const raster::Model model = square_with_alphas(kBlend, {0.25F, 0.5F, 1.0F, 0.75F});
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    EXPECT_EQ(model.parts[0].opacity.mode, raster::AlphaMode::blend);
    ASSERT_EQ(mesh.alphas.size(), mesh.positions.size());
    EXPECT_EQ(sorted(mesh.alphas), (std::vector<float>{0.25F, 0.5F, 0.75F, 1.0F}));
    EXPECT_TRUE(model.warnings.empty()) << testing::PrintToString(model.warnings);
}

TEST(GltfVertexAlpha, OpaqueVerticesAndOpaqueMaterialsKeepNoAlphas) {
    // Every alpha 1: nothing to carry. OPAQUE ignores alpha (glTF 2.0, 3.9.2), so it is not kept either.
    EXPECT_TRUE(square_with_alphas(kBlend, {1.0F, 1.0F, 1.0F, 1.0F}).parts.at(0).mesh.alphas.empty());
    const raster::Model opaque = square_with_alphas(R"({"alphaMode": "OPAQUE"})", {0.0F, 0.0F, 0.0F, 0.0F});
    EXPECT_TRUE(opaque.parts.at(0).mesh.alphas.empty());
    EXPECT_FALSE(opaque.parts.at(0).mesh.colours.empty());
}

TEST(GltfVertexAlpha, ASquareOfAlphaZeroShowsNothingAndOfAlphaOneShows) {
    EXPECT_EQ(pixels_shown(square_with_alphas(kBlend, {0.0F, 0.0F, 0.0F, 0.0F})), 0);
    EXPECT_GT(pixels_shown(square_with_alphas(kBlend, {1.0F, 1.0F, 1.0F, 1.0F})), 100);
    // MASK at 0.5: corners under it cut the square out, corners over it keep it.
    const std::string mask = R"({"alphaMode": "MASK", "alphaCutoff": 0.5})";
    EXPECT_EQ(pixels_shown(square_with_alphas(mask, {0.25F, 0.25F, 0.25F, 0.25F})), 0);
    EXPECT_GT(pixels_shown(square_with_alphas(mask, {0.75F, 0.75F, 0.75F, 0.75F})), 100);
}

TEST(GltfVertexAlpha, AlphasOutsideZeroToOneAreClampedWithOneWarning) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const raster::Model model = square_with_alphas(kBlend, {-1.0F, 2.0F, nan, 0.5F});
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_EQ(sorted(model.parts[0].mesh.alphas), (std::vector<float>{0.0F, 0.5F, 1.0F, 1.0F}));
    std::size_t named = 0;
    for (const std::string& w : model.warnings) named += w.find("3 vertex alphas outside [0, 1]") != std::string::npos;
    EXPECT_EQ(named, 1U) << testing::PrintToString(model.warnings);
}
