// Where weak methods fail on meshes, and what the product does there instead.
#include <raster/geometry/shapes.hpp>
#include <raster/rasterize/draw_mesh.hpp>
#include <raster/render/scene.hpp>
#include <raster/shade/shaders.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <tuple>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

constexpr raster::Rgb kBase{200, 100, 50};
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

std::shared_ptr<const raster::Mesh> shared(raster::Mesh mesh) {
    return std::make_shared<const raster::Mesh>(std::move(mesh));
}

// The colours that appear in an image besides the background.
std::set<std::tuple<int, int, int>> colours_in(const Framebuffer& image, raster::Rgb background) {
    std::set<std::tuple<int, int, int>> colours;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb c = image.pixel(x, y);
            if (c != background) colours.insert({c.r, c.g, c.b});
        }
    }
    return colours;
}

}  // namespace

TEST(MeshStability, ZeroAndNaNNormalsShadeAsAmbientNeverNaN) {
    // The weak way, normalising blindly, turns a zero normal into NaN.
    EXPECT_TRUE(std::isnan(glm::normalize(glm::vec3(0.0F)).x));
    raster::Mesh sphere = raster::sphere(2);
    for (std::size_t i = 0; i < sphere.normals.size(); ++i)
        sphere.normals[i] = i % 2 == 0 ? glm::vec3(0.0F) : glm::vec3(kNaN);
    const auto mesh = shared(sphere);
    const raster::Rgb ambient = raster::scaled_colour(kBase, 0.25F);
    for (const auto method : {raster::ShadingMethod::gouraud, raster::ShadingMethod::phong}) {
        raster::Scene scene{raster::OrthoCamera(60, 40), {0, 0, 0}, {{{1, 1, -1}}}, {}, {}};
        scene.objects.push_back({mesh, glm::mat4(0.8F), raster::IntensityMaterial::shiny(kBase, 0.25F, 30.0F), method});
        scene.objects.back().model[3][3] = 1.0F;
        Framebuffer image(60, 40);
        raster::DepthBuffer depth;
        EXPECT_GT(raster::render(image, scene, depth), 0U);
        EXPECT_EQ(colours_in(image, {0, 0, 0}),
                  (std::set<std::tuple<int, int, int>>{{ambient.r, ambient.g, ambient.b}}));
    }
}

TEST(MeshStability, NonFiniteModelsDrawNothingAndUnusableLightsLeaveAmbient) {
    const auto mesh = shared(raster::torus(12, 8));
    for (const float bad : {kNaN, kInf, -kInf}) {
        raster::Scene scene{raster::OrthoCamera(60, 40), {9, 9, 9}, {{{1, 1, -1}}}, {}, {}};
        glm::mat4 model(0.5F);
        model[3][3] = 1.0F;
        model[1][2] = bad;
        scene.objects.push_back(
            {mesh, model, raster::IntensityMaterial::matte(kBase, 0.25F), raster::ShadingMethod::phong});
        Framebuffer image(60, 40);
        raster::DepthBuffer depth;
        EXPECT_EQ(raster::render(image, scene, depth), 0U) << bad;
        EXPECT_TRUE(colours_in(image, {9, 9, 9}).empty()) << bad;
    }
    raster::Scene dark{raster::OrthoCamera(60, 40), {0, 0, 0}, {{{kNaN, 1, -1}}, {{0, 0, 0}}, {{kInf, 0, 0}}}, {}, {}};
    dark.objects.push_back(
        {shared(raster::sphere(3)), glm::mat4(1.0F), raster::IntensityMaterial::shiny(kBase, 0.25F, 8.0F)});
    Framebuffer image(60, 40);
    raster::DepthBuffer depth;
    raster::render(image, dark, depth);
    const raster::Rgb ambient = raster::scaled_colour(kBase, 0.25F);
    EXPECT_EQ(colours_in(image, {0, 0, 0}), (std::set<std::tuple<int, int, int>>{{ambient.r, ambient.g, ambient.b}}));
}

// A disc cut into 720 slivers, plus facets of zero area (a repeated corner, three collinear
// corners): every pixel centre inside is drawn exactly once, and nothing else is.
TEST(MeshStability, SliversAndZeroAreaFacetsCoverTheDiscExactlyOnce) {
    raster::Mesh disc;
    disc.positions.push_back({0, 0, 0});
    constexpr int kSlivers = 720;
    for (int i = 0; i < kSlivers; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / kSlivers;
        disc.positions.push_back(
            {static_cast<float>(0.9 * std::cos(angle)), static_cast<float>(0.9 * std::sin(angle)), 0});
    }
    for (std::uint32_t i = 0; i < kSlivers; ++i) {
        // Counter-clockwise in the world is clockwise on screen (y flips): facing the camera.
        disc.facets.push_back({{0, 1 + (i + 1) % kSlivers, 1 + i}, {0, 0, -1}});
    }
    disc.facets.push_back({{1, 1, 2}, {0, 0, -1}});
    disc.positions.push_back({0.45F, 0, 0});  // halfway along the first spoke: collinear
    disc.facets.push_back({{0, static_cast<std::uint32_t>(kSlivers + 1), 1}, {0, 0, -1}});
    disc.normals.assign(disc.positions.size(), glm::vec3(0, 0, -1));
    disc.surface = raster::Surface::faceted;
    const raster::OrthoCamera camera(81, 81);  // 40 px per unit: the disc's radius is 36 px
    std::vector<int> hits(81 * 81, 0);
    const raster::IntensityLighting paint({{255, 255, 255}, 1.0F, 0.0F, {}}, {}, {0, 0, -1});
    for (const raster::Facet& facet : disc.facets) {
        raster::Mesh one = disc;
        one.facets = {facet};
        Framebuffer image(81, 81);
        raster::draw_mesh({image}, camera, one, raster::FlatShader{&paint});
        for (int y = 0; y < 81; ++y) {
            for (int x = 0; x < 81; ++x)
                hits[static_cast<std::size_t>(y * 81 + x)] += image.pixel(x, y).r == 255 ? 1 : 0;
        }
    }
    for (int y = 0; y < 81; ++y) {
        for (int x = 0; x < 81; ++x) {
            const double r = std::hypot(x - 40.0, y - 40.0);
            const int count = hits[static_cast<std::size_t>(y * 81 + x)];
            EXPECT_LE(count, 1) << x << ", " << y;
            if (r < 35.5) {
                EXPECT_EQ(count, 1) << x << ", " << y;
            } else if (r > 36.5) {
                EXPECT_EQ(count, 0) << x << ", " << y;
            }
        }
    }
}
