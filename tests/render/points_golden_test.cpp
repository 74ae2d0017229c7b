// Pictures of test-written point clouds and wireframes, and the same picture on any number of
// threads (doc/conventions.md#points-and-lines).
#include <raster/geometry/shapes.hpp>
#include <raster/render/scene.hpp>

#include "support/golden.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

// n points spread evenly over the unit sphere on a golden-angle spiral, each with its outward
// normal and a colour from its position.
std::shared_ptr<raster::Mesh> fibonacci_sphere(std::size_t n) {
    auto mesh = std::make_shared<raster::Mesh>();
    const double turn = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        const double r = std::sqrt(1.0 - y * y), a = turn * static_cast<double>(i);
        const glm::vec3 p(static_cast<float>(r * std::cos(a)), static_cast<float>(y),
                          static_cast<float>(r * std::sin(a)));
        mesh->positions.push_back(p);
        mesh->normals.push_back(p);
        mesh->colours.push_back({0.5F + 0.5F * p.x, 0.5F + 0.5F * p.y, 0.5F + 0.5F * p.z});
        mesh->points.push_back(static_cast<std::uint32_t>(i));
    }
    return mesh;
}

// A sphere's edges as segments, each once, with a colour per vertex and no normals: a wireframe.
std::shared_ptr<raster::Mesh> wire_sphere() {
    auto mesh = std::make_shared<raster::Mesh>(raster::sphere(1));
    std::map<std::pair<std::uint32_t, std::uint32_t>, bool> seen;
    for (const raster::Facet& facet : mesh->facets) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = facet.corners[k], b = facet.corners[(k + 1) % 3];
            if (!seen.emplace(std::pair{std::min(a, b), std::max(a, b)}, true).second) continue;
            mesh->segments.push_back({a, b});
        }
    }
    mesh->facets.clear();
    for (glm::vec3& n : mesh->normals) n = glm::vec3(0.0F);
    for (const glm::vec3& p : mesh->positions) mesh->colours.push_back({0.6F + 0.4F * p.x, 0.6F + 0.4F * p.y, 1.0F});
    return mesh;
}

const raster::LinearMaterial kMatte{{0, 0, 0}, {1, 1, 1}, {0.3F, 0.3F, 0.3F}, 20.0F};

raster::Scene scene_of(std::shared_ptr<raster::Mesh> mesh, int size) {
    raster::Scene scene{raster::OrthoCamera::look_at(size, size, {0.0F, 0.6F, -2.5F}), {20, 22, 28}, {}, {}, {}};
    scene.lights = {{{-0.5F, 0.8F, -0.6F}, 1.0F}};
    scene.objects.push_back({std::move(mesh), glm::mat4(0.8F), kMatte, raster::ShadingMethod::phong});
    scene.objects.front().model[3][3] = 1.0F;
    return scene;
}

}  // namespace

TEST(Golden, PointCloudOfAFibonacciSphereReadsAsASurface) {
    const raster::Scene scene = scene_of(fibonacci_sphere(4000), 128);
    Framebuffer image(128, 128);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, {.samples = 4});
    EXPECT_TRUE(test_support::matches_snapshot(image, "points-fibonacci-sphere"));
}

TEST(Golden, WireframeSphereInPerspective) {
    raster::Scene scene = scene_of(wire_sphere(), 128);
    scene.objects.push_back({fibonacci_sphere(300), glm::mat4(0.5F), kMatte, raster::ShadingMethod::phong});
    scene.objects.back().model[3][3] = 1.0F;
    scene.points_and_lines.point_size = 5.0;
    Framebuffer image(128, 128);
    raster::DepthBuffer depth;
    raster::render(image, raster::in_perspective(scene, 128, 128, 50.0), depth, {.samples = 8});
    EXPECT_TRUE(test_support::matches_snapshot(image, "lines-wire-sphere"));
}

TEST(PointsAndLinesThreads, ThePictureIsTheSameOnAnyNumberOfThreads) {
    raster::Scene scene = scene_of(fibonacci_sphere(30000), 96);
    scene.objects.push_back({wire_sphere(), glm::mat4(1.0F), kMatte, raster::ShadingMethod::gouraud});
    for (const int samples : {1, 4}) {
        Framebuffer one(96, 96);
        raster::DepthBuffer depth;
        raster::render(one, scene, depth, {.threads = 1, .samples = samples});
        for (const int threads : {2, 3, 8}) {
            Framebuffer many(96, 96);
            raster::render(many, scene, depth, {.threads = threads, .samples = samples});
            EXPECT_TRUE(std::equal(one.pixels(), one.pixels() + 96 * 96 * 3, many.pixels()))
                << threads << " threads, " << samples << " samples";
        }
    }
}

// A cloud big enough to be drawn in several rounds of batches draws as its points would one
// after another: here as slices of it, each a small object of its own, drawn in order. Each spot
// is taken by many points of different colours at one depth, so the last one drawn shows.
TEST(PointsAndLinesThreads, ACloudDrawnInRoundsIsItsPointsDrawnInTheirOrder) {
    constexpr std::size_t kSpots = 1000, kPoints = 400 * kSpots, kSlice = 10000;
    const std::shared_ptr<raster::Mesh> spots = fibonacci_sphere(kSpots);
    auto cloud = std::make_shared<raster::Mesh>();
    for (std::size_t i = 0; i < kPoints; ++i) {
        cloud->points.push_back(static_cast<std::uint32_t>(i));
        cloud->positions.push_back(spots->positions[i % kSpots]);
        cloud->normals.push_back(glm::vec3(0.0F));  // drawn in their colours
        const auto shade = [&](std::size_t k) { return static_cast<float>((i * k) % 251) / 250.0F; };
        cloud->colours.push_back({shade(7), shade(13), shade(31)});
    }
    raster::Scene whole = scene_of(cloud, 96);
    whole.points_and_lines.point_size = 3.0;
    raster::Scene sliced = whole;
    sliced.objects.clear();
    for (std::size_t begin = 0; begin < kPoints; begin += kSlice) {
        auto slice = std::make_shared<raster::Mesh>();
        for (std::size_t i = begin; i < begin + kSlice; ++i) {
            slice->points.push_back(static_cast<std::uint32_t>(slice->positions.size()));
            slice->positions.push_back(cloud->positions[i]);
            slice->normals.push_back(cloud->normals[i]);
            slice->colours.push_back(cloud->colours[i]);
        }
        sliced.objects.push_back(whole.objects.front());
        sliced.objects.back().mesh = std::move(slice);
    }
    for (const int samples : {1, 4}) {
        for (const int threads : {1, 3}) {
            Framebuffer expected(96, 96), drawn(96, 96);
            raster::DepthBuffer depth;
            raster::render(expected, sliced, depth, {.threads = threads, .samples = samples});
            raster::render(drawn, whole, depth, {.threads = threads, .samples = samples});
            EXPECT_TRUE(std::equal(expected.pixels(), expected.pixels() + 96 * 96 * 3, drawn.pixels()))
                << threads << " threads, " << samples << " samples";
        }
    }
}
