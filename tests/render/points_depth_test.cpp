// Points and lines depth-tested with the surfaces: hidden behind, shown in front, and not cut by
// the surface they lie on (doc/conventions.md#points-and-lines).
#include <raster/render/scene.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

// A red unlit square over the whole 11 x 11 view at z = 0, facing the camera at z = -5, turned
// by `degrees` about the vertical axis.
raster::SceneObject red_square(float degrees) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions = {{-2.0F, -2.0F, 0.0F}, {2.0F, -2.0F, 0.0F}, {2.0F, 2.0F, 0.0F}, {-2.0F, 2.0F, 0.0F}};
    mesh->normals.assign(4, {0.0F, 0.0F, -1.0F});
    const glm::vec3 behind(0.0F, 0.0F, 1.0F);
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0F), glm::radians(degrees), glm::vec3(0.0F, 1.0F, 0.0F));
    return {mesh, turn, raster::LinearMaterial{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {}}, raster::ShadingMethod::unlit};
}

// A green point 7 pixels across at the view's centre and a green line 3 wide across it, at depth z
// on the square turned by `degrees` (z = 0: on it).
raster::SceneObject green_marks(float z, float degrees) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions = {{0.0F, 0.0F, z}, {-0.8F, -0.6F, z}, {0.8F, -0.6F, z}};
    mesh->normals.assign(3, glm::vec3(0.0F));  // no normals: drawn in their colour
    mesh->points = {0};
    mesh->segments = {{1, 2}};
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0F), glm::radians(degrees), glm::vec3(0.0F, 1.0F, 0.0F));
    return {mesh, turn, raster::LinearMaterial{{0, 0, 0}, {0, 1, 0}, {0, 0, 0}, {}}, raster::ShadingMethod::phong};
}

// How many pixels are pure green, and how many pure red.
std::pair<int, int> green_and_red(float z, float degrees, int samples, bool perspective, bool square = true) {
    raster::Scene scene{raster::OrthoCamera::look_at(11, 11, {0.0F, 0.0F, -5.0F}), {0, 0, 0}, {}, {}, {}};
    scene.objects = {red_square(degrees), green_marks(z, degrees)};
    if (!square) scene.objects.front().mesh.reset();
    scene.points_and_lines.point_size = 7.0;
    scene.points_and_lines.line_width = 3.0;
    Framebuffer image(11, 11);
    raster::DepthBuffer depth;
    if (perspective) {
        raster::render(image, raster::in_perspective(scene, 11, 11, 30.0), depth, {.samples = samples});
    } else {
        raster::render(image, scene, depth, {.samples = samples});
    }
    int green = 0, red = 0;
    for (int y = 0; y < 11; ++y) {
        for (int x = 0; x < 11; ++x) {
            green += image.pixel(x, y) == raster::Rgb{0, 255, 0} ? 1 : 0;
            red += image.pixel(x, y) == raster::Rgb{255, 0, 0} ? 1 : 0;
        }
    }
    return {green, red};
}

}  // namespace

TEST(PointsAndLinesDepth, BehindASurfaceAreHiddenAndInFrontAreShown) {
    for (const bool perspective : {false, true}) {
        for (const int samples : {1, 2, 4, 8, 16}) {
            // 1.5 from the square: farther than the splat's radius (0.7) and the line's half width.
            const auto [hidden_green, hidden_red] = green_and_red(1.5F, 0.0F, samples, perspective);
            EXPECT_EQ(hidden_green, 0) << samples << (perspective ? " in perspective" : "");
            EXPECT_EQ(hidden_red, 121) << samples;
            const int alone = green_and_red(-1.5F, 0.0F, samples, perspective, false).first;
            const auto [shown_green, shown_red] = green_and_red(-1.5F, 0.0F, samples, perspective);
            EXPECT_EQ(shown_green, alone) << samples << (perspective ? " in perspective" : "");
            EXPECT_GT(alone, 30) << samples;
            EXPECT_LE(shown_red, 121 - alone) << samples;
        }
    }
}

TEST(PointsAndLinesDepth, OnASlopingSurfaceTheyAreNotCutByIt) {
    // On the square turned 40 degrees the surface at a splat's rim lies 0.84 of its radius nearer
    // or farther: tested at their own centre depth, half the splat and half the line would sink.
    for (const bool perspective : {false, true}) {
        for (const int samples : {1, 4, 16}) {
            const int alone = green_and_red(0.0F, 40.0F, samples, perspective, false).first;
            const auto [on_green, on_red] = green_and_red(0.0F, 40.0F, samples, perspective);
            EXPECT_EQ(on_green, alone) << samples << (perspective ? " in perspective" : "");
            EXPECT_GT(alone, 30) << samples;
            EXPECT_GT(on_red, 0) << samples;
        }
    }
}
