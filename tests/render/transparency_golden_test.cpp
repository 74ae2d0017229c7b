// Pictures of transparency, looked at: layers blended in depth order over a lit sphere, and a
// checker cut out by its texture's alpha with anti-aliased edges (doc/conventions.md#transparency).
#include <raster/geometry/shapes.hpp>
#include <raster/render/scene.hpp>

#include "support/golden.hpp"

#include <cstdint>
#include <memory>
#include <vector>
#include <glm/ext/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace {

// A square of side 2 about the origin in the xy plane, facing the camera at -z, with texture coordinates.
std::shared_ptr<const raster::Mesh> unit_square() {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh->normals.assign(4, {0, 0, -1});
    mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const glm::vec3 behind(0, 0, 1);
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    return mesh;
}

raster::SceneObject object(std::shared_ptr<const raster::Mesh> mesh, const glm::mat4& model, raster::LinearRgb colour,
                           raster::Opacity opacity, raster::ShadingMethod shading = raster::ShadingMethod::phong) {
    raster::SceneObject o{std::move(mesh), model, raster::LinearMaterial{{0, 0, 0}, colour, {0.2F, 0.2F, 0.2F}, 32.0F},
                          shading};
    o.opacity = opacity;
    return o;
}

glm::mat4 placed(glm::vec3 at, float scale, float turn_y) {
    return glm::scale(glm::rotate(glm::translate(glm::mat4(1.0F), at), turn_y, glm::vec3(0, 1, 0)), glm::vec3(scale));
}

}  // namespace

TEST(TransparencyGolden, LayersOverASphereBlendInDepthOrder) {
    raster::Scene scene{raster::OrthoCamera(160, 120), {40, 40, 48}, {{{0.5F, 1.0F, -1.0F}}}, {}, {}};
    const auto square = unit_square();
    const raster::Opacity half{raster::AlphaMode::blend, 0.5F, 0.5F};
    scene.objects.push_back(object(square, placed({0.25F, 0.1F, -0.2F}, 0.45F, 0.5F), {0.9F, 0.1F, 0.05F}, half));
    scene.objects.push_back(object(square, placed({-0.3F, 0.0F, 0.1F}, 0.5F, -0.6F), {0.05F, 0.6F, 0.1F}, half));
    scene.objects.push_back(object(std::make_shared<raster::Mesh>(raster::sphere(4)),
                                   glm::scale(glm::mat4(1.0F), glm::vec3(0.35F)), {0.8F, 0.8F, 0.8F}, {}));
    scene.objects.push_back(object(square, placed({0.0F, -0.25F, -0.5F}, 0.4F, 0.2F), {0.1F, 0.2F, 0.9F},
                                   {raster::AlphaMode::blend, 0.35F, 0.5F}));
    raster::Framebuffer image(160, 120);
    raster::Renderer renderer({.threads = 2, .samples = 4});
    renderer.render(image, scene);
    EXPECT_TRUE(test_support::matches_snapshot(image, "transparent_layers"));
}

TEST(TransparencyGolden, ACheckerMaskedByItsAlphaHasSmoothEdges) {
    // An 8 x 8 checker, orange texels opaque and the others alpha 0, over a blue square behind.
    std::vector<std::uint8_t> rgb, alpha;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            const bool on = (x + y) % 2 == 0;
            rgb.insert(rgb.end(), {240, 150, 30});
            alpha.push_back(on ? 255 : 0);
        }
    }
    const auto texture = std::make_shared<const raster::Texture>(raster::Framebuffer(8, 8, rgb), alpha);
    raster::Scene scene{raster::OrthoCamera(128, 96), {0, 0, 0}, {{{0, 0, -1}}}, {}, {}};
    const auto square = unit_square();
    raster::SceneObject checker = object(square, placed({0, 0, 0}, 0.7F, 0.5F), {1, 1, 1},
                                         {raster::AlphaMode::mask, 1.0F, 0.5F}, raster::ShadingMethod::unlit);
    checker.texture = texture;
    checker.sampler = {raster::TextureFilter::bilinear, raster::TextureWrap::clamp};
    checker.model = glm::rotate(checker.model, 0.3F, glm::vec3(0, 0, 1));
    scene.objects.push_back(checker);
    scene.objects.push_back(
        object(square, placed({0, 0, 1}, 0.9F, 0.0F), {0.1F, 0.2F, 0.8F}, {}, raster::ShadingMethod::unlit));
    raster::Framebuffer image(128, 96);
    raster::Renderer renderer({.threads = 2, .samples = 8});
    renderer.render(image, scene);
    EXPECT_TRUE(test_support::matches_snapshot(image, "alpha_masked_checker"));
}
