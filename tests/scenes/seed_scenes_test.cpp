// The Ptah and raster-engine scenes, their primitives, and depth darkening.
#include <raster/geometry/primitives.hpp>
#include <raster/scenes/seed_scenes.hpp>
#include <raster/shade/linear_lighting.hpp>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace {

// Every facet's normal points away from `inside`, every vertex has a texture coordinate.
void expect_outward(const raster::Mesh& mesh, glm::vec3 inside) {
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const raster::Facet& facet : mesh.facets) {
        const glm::vec3 a = mesh.positions[facet.corners[0]], b = mesh.positions[facet.corners[1]],
                        c = mesh.positions[facet.corners[2]];
        EXPECT_EQ(raster::facet_normal(a, b, c), facet.normal);
        EXPECT_GT(glm::dot(facet.normal, (a + b + c) / 3.0F - inside), 0.0F);
    }
}

}  // namespace

TEST(Primitives, BoxesPyramidsAndGroundFaceOutwardWithTextureCoordinates) {
    const raster::Mesh box = raster::textured_box({2, 4, 6}, 2.0F);
    EXPECT_EQ(box.facets.size(), 12U);
    expect_outward(box, glm::vec3(0.0F));
    // Texture coordinates run in world units over the tile: the 6-unit side spans 3 repeats.
    float low = 1e9F, high = -1e9F;
    for (const glm::vec2 uv : box.uvs) low = std::min(low, uv.x), high = std::max(high, uv.x);
    EXPECT_FLOAT_EQ(high - low, 3.0F);
    const raster::Mesh pyramid = raster::textured_pyramid(2, 2, 3);
    EXPECT_EQ(pyramid.facets.size(), 6U);
    expect_outward(pyramid, glm::vec3(0, 0.5F, 0));
    const raster::Mesh ground = raster::textured_ground(10, 10);
    ASSERT_EQ(ground.facets.size(), 2U);
    EXPECT_EQ(ground.facets[0].normal, glm::vec3(0, 1, 0));
}

TEST(Primitives, TheTorusKnotsNormalsLeaveItsTube) {
    const raster::Mesh knot = raster::torus_knot(2, 3, 0.2F, 256, 16, 4.0F);
    EXPECT_EQ(knot.facets.size(), 256U * 16U * 2U);
    for (const raster::Facet& facet : knot.facets) {
        const glm::vec3 n = knot.normals[facet.corners[0]];
        EXPECT_GT(glm::dot(facet.normal, n), 0.7F);  // the facet faces the way its corner's normal does
    }
}

TEST(DepthDarkening, LightFallsLinearlyFromStartToTheFloorAtEnd) {
    const raster::DepthDarkening dark{10.0F, 30.0F, 0.2F};
    EXPECT_EQ(dark.factor(-5.0F), 1.0F);
    EXPECT_EQ(dark.factor(10.0F), 1.0F);
    EXPECT_FLOAT_EQ(dark.factor(20.0F), 0.6F);
    EXPECT_EQ(dark.factor(30.0F), 0.2F);
    EXPECT_EQ(dark.factor(1e30F), 0.2F);
    // In a lighting model with an eye, the same surface point receives less light farther away.
    const raster::LinearMaterial white{{}, {1, 1, 1}, {}, std::nullopt};
    const raster::DirectionalLight sun{{0, 1, 0}, 1.0F};
    const raster::LinearLighting lit(white, std::span(&sun, 1), {}, {0, 0, -1}, glm::vec3(0, 0, 0), dark);
    EXPECT_FLOAT_EQ(lit.shade({0, 0, 5}, {0, 1, 0}).r, 1.0F);
    EXPECT_FLOAT_EQ(lit.shade({0, 0, 20}, {0, 1, 0}).r, 0.6F);
    EXPECT_FLOAT_EQ(lit.shade({0, 0, 50}, {0, 1, 0}).r, 0.2F);
}

TEST(SeedScenes, PtahKeepsTheArticlesCameraLightAndBackground) {
    const raster::SeedScene ptah("ptah");
    const raster::PerspectiveScene scene = ptah.still(800, 600);
    EXPECT_EQ(scene.camera.eye(), glm::vec3(-2.0F, 0.5F, 0.0F));
    EXPECT_EQ(scene.camera.lens().fov_y_degrees, 70.0);
    EXPECT_EQ(scene.camera.lens().near, 0.5);
    EXPECT_EQ(scene.camera.lens().far, 10.0);
    EXPECT_EQ(scene.background, (raster::Rgb{128, 128, 255}));
    ASSERT_EQ(scene.lights.size(), 1U);
    EXPECT_EQ(scene.lights[0].toward, glm::normalize(glm::vec3(0, 1, -1)));  // the article's (0, 1, 1), z mirrored
    ASSERT_EQ(scene.objects.size(), 1U);
    const glm::mat4 expected = glm::rotate(glm::scale(glm::mat4(1.0F), glm::vec3(0.5F)), 1.7F, glm::vec3(0, 1, 0));
    EXPECT_EQ(scene.objects[0].model, expected);
    EXPECT_NE(scene.objects[0].texture, nullptr);
}

TEST(SeedScenes, TheFlightLoopsTheBoatSailsAndDepthDarkens) {
    const raster::SeedScene fly("flythrough");
    const int count = fly.info().frames;
    const raster::PerspectiveScene first = fly.frame(320, 240, 0, count), later = fly.frame(320, 240, count / 4, count);
    ASSERT_TRUE(first.darkening.has_value());
    EXPECT_NE(first.camera.eye(), later.camera.eye());
    EXPECT_NE(first.objects.back().model, later.objects.back().model);  // the boat
    const raster::PerspectiveScene again = fly.frame(320, 240, count, count);
    EXPECT_LT(glm::length(again.camera.eye() - first.camera.eye()), 1e-4F);
    for (const raster::SceneObject& object : first.objects) EXPECT_NE(object.texture, nullptr);
    EXPECT_TRUE(raster::is_seed_scene("flythrough"));
    EXPECT_FALSE(raster::is_seed_scene("torus"));
    EXPECT_THROW(raster::SeedScene("atlantis"), std::invalid_argument);
}
