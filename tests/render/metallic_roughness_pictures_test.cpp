// Pictures of the metallic-roughness material, written here and compared with snapshots/pbr/:
// a grid of spheres from dielectric to metal and smooth to rough, a normal-mapped quad and a glowing one.
#include <raster/geometry/shapes.hpp>
#include <raster/geometry/tangents.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>
#include <raster/shade/metallic_roughness.hpp>

#include "support/golden.hpp"

#include <cmath>
#include <memory>
#include <vector>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::LinearRgb;
using raster::MetallicRoughness;
using raster::PerspectiveCamera;
using raster::PerspectiveScene;

namespace {

// A camera on -z looking at the origin, a key light from above left, and the built-in studio.
PerspectiveScene studio_scene(int width, int height, float distance) {
    return PerspectiveScene{
        PerspectiveCamera::look_at(width, height, {0, 0, -distance}, {0, 0, 0}, {0, 1, 0}, {30.0, 0.1, 100.0}),
        {0, 0, 0},
        {{{-1.0F, 1.0F, -1.0F}, 0.8F}},
        {},
        {}};
}

Framebuffer drawn(const PerspectiveScene& scene, int width, int height) {
    Framebuffer image(width, height);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, {.samples = raster::kSmoothSamples});
    return image;
}

// A unit square facing the camera (-z), u along +x and v along +y.
std::shared_ptr<const raster::Mesh> facing_square() {
    raster::Mesh mesh;
    mesh.positions = {{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
    mesh.normals.assign(4, glm::vec3(0, 0, -1));
    mesh.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    mesh.facets = {{{0, 1, 2}, {0, 0, -1}}, {{0, 2, 3}, {0, 0, -1}}};
    mesh.convex = true;
    return std::make_shared<const raster::Mesh>(std::move(mesh));
}

}  // namespace

// Columns run from dielectric (left) to metal (right), rows from smooth (top) to rough (bottom).
TEST(Golden, MetallicRoughnessSpheresFromDielectricToMetalAndSmoothToRough) {
    constexpr int kSteps = 5;
    PerspectiveScene scene = studio_scene(250, 250, 8.5F);
    const auto sphere = std::make_shared<const raster::Mesh>(raster::sphere(4));
    for (int row = 0; row < kSteps; ++row) {
        for (int column = 0; column < kSteps; ++column) {
            MetallicRoughness m;
            m.base_colour = {0.9F, 0.45F, 0.2F};
            m.metallic = static_cast<float>(column) / (kSteps - 1);
            m.roughness = static_cast<float>(row) / (kSteps - 1);
            const glm::vec3 at(static_cast<float>(column - 2) * 0.8F, static_cast<float>(2 - row) * 0.8F, 0.0F);
            scene.objects.push_back({sphere, glm::scale(glm::translate(glm::mat4(1.0F), at), glm::vec3(0.36F)), m});
        }
    }
    EXPECT_TRUE(test_support::matches_snapshot(drawn(scene, 250, 250), "pbr/sphere-grid"));
}

namespace {

// Vertical stripes, 4 texels wide, whose normals lean alternately toward -u and +u.
MetallicRoughness striped_normals() {
    std::vector<std::uint8_t> texels;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const bool left = (x / 4) % 2 == 0;
            texels.insert(texels.end(), {static_cast<std::uint8_t>(left ? 64 : 191), 128, 238});
        }
    }
    MetallicRoughness m;
    m.base_colour = {0.6F, 0.6F, 0.6F}, m.metallic = 0.0F, m.roughness = 0.5F;
    m.normal_map =
        std::make_shared<const raster::Texture>(Framebuffer(32, 32, std::move(texels)), raster::TexelEncoding::linear);
    return m;
}

// The facing square with the tangents tangents_from_uvs makes (along +x), or given ones.
std::shared_ptr<const raster::Mesh> tangent_square(const std::vector<glm::vec4>& tangents = {}) {
    raster::Mesh mesh = *facing_square();
    mesh.tangents = tangents.empty() ? raster::tangents_from_uvs(mesh) : tangents;
    return std::make_shared<const raster::Mesh>(std::move(mesh));
}

Framebuffer striped_square(std::shared_ptr<const raster::Mesh> square) {
    PerspectiveScene scene = studio_scene(96, 96, 4.5F);
    scene.lights = {{{-1.0F, 0.2F, -0.4F}, 1.0F}};
    scene.objects.push_back({std::move(square), glm::mat4(1.0F), striped_normals()});
    return drawn(scene, 96, 96);
}

// How alike two pictures' green is along the middle row across the square: the correlation of
// their levels, from 1 (the same pattern) to -1 (bright where the other is dark).
double row_correlation(const Framebuffer& a, const Framebuffer& b) {
    constexpr int kFrom = 24, kTo = 72;
    double mean_a = 0.0, mean_b = 0.0;
    for (int x = kFrom; x < kTo; ++x) mean_a += a.pixel(x, 48).g, mean_b += b.pixel(x, 48).g;
    mean_a /= kTo - kFrom, mean_b /= kTo - kFrom;
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (int x = kFrom; x < kTo; ++x) {
        const double da = a.pixel(x, 48).g - mean_a, db = b.pixel(x, 48).g - mean_b;
        ab += da * db, aa += da * da, bb += db * db;
    }
    return ab / std::sqrt(aa * bb);
}

}  // namespace

// Vertical stripes whose normals lean alternately left and right: lit from the left, they read
// as ridges, though the square is flat.
TEST(Golden, NormalMappedSquareShowsStripesLeaning) {
    EXPECT_TRUE(test_support::matches_snapshot(striped_square(tangent_square()), "pbr/normal-mapped-square"));
}

// The same stripes with every tangent turned a quarter, to +y: their normals lean down and up
// instead of toward and away from the light on the left, and the light from a little above
// brightens the other stripes. The screen's own frame (a mesh without tangents) draws as the
// made tangents do.
TEST(NormalMap, VertexTangentsTurnedAQuarterBrightenTheOtherStripes) {
    const Framebuffer along_u = striped_square(tangent_square());
    const Framebuffer turned = striped_square(tangent_square(std::vector<glm::vec4>(4, {0, 1, 0, -1})));
    const Framebuffer screen = striped_square(facing_square());
    EXPECT_LT(row_correlation(along_u, turned), -0.5);
    EXPECT_GT(row_correlation(along_u, screen), 0.99);
}

// A black square with emissiveFactor (0, 1, 0) glows green whatever the light.
TEST(Golden, EmissiveSquareGlowsGreen) {
    MetallicRoughness m;
    m.base_colour = {0, 0, 0}, m.metallic = 0.0F, m.emissive = {0, 1, 0};
    PerspectiveScene scene = studio_scene(64, 64, 4.5F);
    scene.objects.push_back({facing_square(), glm::mat4(1.0F), m});
    const Framebuffer image = drawn(scene, 64, 64);
    EXPECT_GE(image.pixel(32, 32).g, 250);
    EXPECT_TRUE(test_support::matches_snapshot(image, "pbr/emissive-square"));
}
