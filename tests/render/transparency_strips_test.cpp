// Blend objects over frames of several strips: each strip's fragments gathered into its thread's list, resolved
// and forgotten before the next strip reuses the list (doc/conventions.md#transparency).
#include <raster/image/colour.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <gtest/gtest.h>

namespace {

// A frame tall enough for several strips of rows (a narrow frame's strips are 64 rows).
constexpr int kWidth = 9, kHeight = 200;

// An unlit square of `colour` at depth z facing the camera (which looks along +z), centred on `centre`.
raster::SceneObject square(float z, raster::LinearRgb colour, float alpha, float half, glm::vec2 centre = {0, 0}) {
    auto mesh = std::make_shared<raster::Mesh>();
    const float x0 = centre.x - half, x1 = centre.x + half, y0 = centre.y - half, y1 = centre.y + half;
    mesh->positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    mesh->normals.assign(4, {0.0F, 0.0F, -1.0F});
    const glm::vec3 behind(centre.x, centre.y, z + 1.0F);
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    raster::SceneObject object{mesh, glm::mat4(1.0F), raster::LinearMaterial{{0, 0, 0}, colour, {0, 0, 0}, {}},
                               raster::ShadingMethod::unlit};
    object.opacity = {alpha < 1.0F ? raster::AlphaMode::blend : raster::AlphaMode::opaque, alpha, 0.5F};
    return object;
}

raster::Scene scene_of(std::vector<raster::SceneObject> objects, int width, int height, bool transparent) {
    raster::Scene scene{raster::OrthoCamera(width, height), {0, 0, 0}, {}, {}, {}};
    scene.objects = std::move(objects);
    scene.keep_depth = transparent;
    return scene;
}

struct Drawn {
    std::vector<std::uint8_t> pixels;
    std::vector<std::uint8_t> alpha;
};

Drawn drawn(const raster::Scene& scene, int width, int height, int samples, int threads) {
    raster::Renderer renderer({.threads = threads, .samples = samples});
    raster::Framebuffer image(width, height);
    renderer.render(image, scene);
    return {std::vector<std::uint8_t>(image.pixels(), image.pixels() + static_cast<std::size_t>(width * height * 3)),
            renderer.coverage()};
}

// Eight full layers, far ones first in the file, alpha 1/2 and colours 0 or 1: every step exact in floats.
std::vector<raster::SceneObject> eight_layers() {
    std::vector<raster::SceneObject> layers;
    for (int k = 0; k < 8; ++k) {
        const raster::LinearRgb colour{static_cast<float>(k & 1), static_cast<float>((k >> 1) & 1),
                                       static_cast<float>((k >> 2) & 1)};
        layers.push_back(square(static_cast<float>(8 - k), colour, 0.5F, 500.0F));
    }
    return layers;
}

}  // namespace

TEST(TransparencyStrips, EveryStripOfATallFrameBlendsItsLayersAsOneStripDoes) {
    // A 9 x 9 frame is one strip; the 9 x 200 frame's strips, on one thread or three, must give every pixel the
    // same colour and alpha, whatever the file order.
    std::vector<raster::SceneObject> layers = eight_layers();
    for (const int samples : {1, 4}) {
        const Drawn one = drawn(scene_of(layers, kWidth, kWidth, true), kWidth, kWidth, samples, 1);
        for (const bool reversed : {false, true}) {
            std::vector<raster::SceneObject> order = layers;
            if (reversed) std::reverse(order.begin(), order.end());
            for (const int threads : {1, 3}) {
                const Drawn tall = drawn(scene_of(order, kWidth, kHeight, true), kWidth, kHeight, samples, threads);
                ASSERT_EQ(tall.alpha.size(), static_cast<std::size_t>(kWidth * kHeight));
                for (std::size_t i = 0; i < tall.pixels.size(); ++i)
                    ASSERT_EQ(tall.pixels[i], one.pixels[0 + i % 3]) << "byte " << i << ", " << samples << " samples";
                for (const std::uint8_t a : tall.alpha) ASSERT_EQ(a, 255 - 1) << samples << " samples";  // 1 - 2^-8
            }
        }
    }
}

TEST(TransparencyStrips, AStripWithManyLayersAndItsNeighboursWithFewResolveAlike) {
    // Forty layers over a band in the second strip only (past the small-list sort), one over the rest: drawn with a
    // Renderer kept from frame to frame, in two file orders, on one thread and three.
    std::vector<raster::SceneObject> layers;
    layers.push_back(square(50.0F, {0.0F, 0.0F, 1.0F}, 0.5F, 500.0F));
    for (int k = 0; k < 40; ++k) {
        const raster::LinearRgb colour{static_cast<float>(k % 2), static_cast<float>(k % 3 == 0), 0.0F};
        layers.push_back(square(static_cast<float>(k), colour, 0.25F + 0.0125F * static_cast<float>(k), 1.5F,
                                {0.0F, 2.375F}));  // rows 84 to 96
    }
    std::vector<raster::SceneObject> reversed(layers.rbegin(), layers.rend());
    for (const int samples : {1, 4}) {
        const Drawn first = drawn(scene_of(layers, kWidth, kHeight, false), kWidth, kHeight, samples, 1);
        raster::Renderer kept({.threads = 3, .samples = samples});
        for (int frame = 0; frame < 2; ++frame) {
            for (const auto* order : {&layers, &reversed}) {
                raster::Framebuffer image(kWidth, kHeight);
                kept.render(image, scene_of(*order, kWidth, kHeight, false));
                ASSERT_TRUE(std::equal(first.pixels.begin(), first.pixels.end(), image.pixels()))
                    << samples << " samples, frame " << frame;
            }
        }
        // The band differs from the rows around it, and those are the lone layer's colour.
        const std::size_t row = static_cast<std::size_t>(kWidth) * 3;
        EXPECT_NE(first.pixels[row * std::size_t{90} + 12], first.pixels[12]);  // row 90, in the band
        EXPECT_EQ(first.pixels[row * 2 + 2], raster::srgb_byte_from_linear(0.5F));
    }
}
