// raster-engine's render modes: flat colours and wireframes, on any scene.
#include <raster/geometry/primitives.hpp>
#include <raster/render/render_style.hpp>

#include "support/picture.hpp"

#include <gtest/gtest.h>

namespace {

constexpr raster::Rgb kWhite{255, 255, 255};

// A 2 x 2 square at z = 0 facing -Z, seen head on through a 90-degree pinhole from `eye_z`.
raster::PerspectiveScene square_from(float eye_z) {
    raster::Mesh square = raster::textured_quad(
        {glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(1, 1, 0), glm::vec3(-1, 1, 0)}, glm::vec3(0, 0, 1));
    const auto camera =
        raster::PerspectiveCamera::look_at(9, 9, {0, 0, eye_z}, glm::vec3(0), {0, 1, 0}, {90.0, 0.1, 10.0});
    raster::SceneObject object{std::make_shared<const raster::Mesh>(std::move(square)), glm::mat4(1.0F),
                               raster::LinearMaterial{{}, {1, 1, 1}, {}, std::nullopt}};
    return {camera, raster::Rgb{0, 0, 0}, {}, {}, {object}};
}

}  // namespace

TEST(RenderStyle, AWireframeDrawsTheEdgesOfEveryFacetFacingTheEye) {
    raster::Framebuffer image(9, 9);
    EXPECT_EQ(raster::draw_wireframe(image, square_from(-2.0F)), 2U);
    EXPECT_TRUE(test_support::looks_like(image,
                                         {".........", ".........", "..#####..", "..#..##..", "..#.#.#..", "..##..#..",
                                          "..#####..", ".........", "........."},
                                         {{'#', kWhite}}));
}

TEST(RenderStyle, AWireframeCullsFacetsTurnedAway) {
    raster::Framebuffer image(9, 9);
    EXPECT_EQ(raster::draw_wireframe(image, square_from(2.0F)), 0U);
    EXPECT_TRUE(test_support::looks_like(image, std::vector<std::string>(9, ".........")));
}

TEST(RenderStyle, AWireframeClipsEdgesThatPassBehindTheEye) {
    // A floor running from behind the eye to far ahead: its edges are cut at the near plane, so
    // they reach the bottom of the picture instead of wrapping round through infinity.
    raster::Mesh floor = raster::textured_quad(
        {glm::vec3(-1, -1, -5), glm::vec3(1, -1, -5), glm::vec3(1, -1, 5), glm::vec3(-1, -1, 5)}, glm::vec3(0, -2, 0));
    const auto camera = raster::PerspectiveCamera::look_at(9, 9, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {90.0, 0.1, 10.0});
    raster::SceneObject object{std::make_shared<const raster::Mesh>(std::move(floor)), glm::mat4(1.0F),
                               raster::IntensityMaterial{kWhite, 1.0F, 0.0F, std::nullopt}};
    raster::Framebuffer image(9, 9);
    EXPECT_EQ(raster::draw_wireframe(image, raster::PerspectiveScene{camera, raster::Rgb{0, 0, 0}, {}, {}, {object}}),
              2U);
    // The far edge at z = 5 is three pixels wide on row 5; the sides and the diagonal run down
    // out of the picture (the diagonal, cut at z = 0.1, stays near x = 0.2 NDC, column 5).
    EXPECT_TRUE(test_support::looks_like(image,
                                         {".........", ".........", ".........", ".........", ".........", "...###...",
                                          "..#..##..", ".#...#.#.", "#....#..#"},
                                         {{'#', kWhite}}));
}

TEST(RenderStyle, FlatStyleLightsEachSurfaceInItsTexturesMeanColourPerFacet) {
    raster::Framebuffer checks(2, 2);
    checks.set_pixel(0, 0, {255, 0, 0});
    checks.set_pixel(1, 1, {255, 0, 0});
    checks.set_pixel(1, 0, {0, 0, 255});
    checks.set_pixel(0, 1, {0, 0, 255});
    raster::PerspectiveScene scene = square_from(-2.0F);
    scene.objects[0].texture = std::make_shared<const raster::Texture>(std::move(checks));
    const raster::PerspectiveScene flat = raster::flat_style(scene);
    ASSERT_EQ(flat.objects.size(), 1U);
    EXPECT_EQ(flat.objects[0].texture, nullptr);
    EXPECT_EQ(flat.objects[0].shading, raster::ShadingMethod::flat);
    const auto& material = std::get<raster::LinearMaterial>(flat.objects[0].material);
    // Red and blue averaged in linear light, to within the sRGB byte the 1 x 1 level is kept in.
    EXPECT_NEAR(material.diffuse.r, 0.5F, 0.005F);
    EXPECT_EQ(material.diffuse.g, 0.0F);
    EXPECT_NEAR(material.diffuse.b, 0.5F, 0.005F);
    EXPECT_NE(scene.objects[0].texture, nullptr);  // the scene given is left as it was
}
