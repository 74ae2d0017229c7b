#include <raster/scenes/scenes.hpp>

#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/cube.hpp>
#include <raster/rasterize/draw_cube.hpp>
#include <raster/rasterize/line.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/palette.hpp>

#include <cmath>
#include <numbers>
#include <glm/ext/matrix_transform.hpp>

namespace raster {
namespace {

constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0F;
constexpr glm::vec3 kAxisX{1.0F, 0.0F, 0.0F};
constexpr glm::vec3 kAxisY{0.0F, 1.0F, 0.0F};
constexpr glm::vec3 kAxisZ{0.0F, 0.0F, 1.0F};
constexpr int kSpokeCount = 72;

glm::mat4 half_size() { return glm::scale(glm::mat4(1.0F), glm::vec3(0.5F)); }

}  // namespace

glm::mat4 still_cube_pose() {
    const glm::mat4 identity(1.0F);
    return glm::rotate(identity, kQuarterPi, kAxisX) * glm::rotate(identity, kQuarterPi, kAxisY) * half_size();
}

glm::mat4 tumble_rotation(float t) {
    const glm::mat4 identity(1.0F);
    return glm::rotate(identity, t, kAxisZ) * glm::rotate(identity, t, kAxisY) * glm::rotate(identity, t, kAxisX);
}

float tumble_angle(int frame, int frame_count) {
    return 2.0F * std::numbers::pi_v<float> * static_cast<float>(frame) / static_cast<float>(frame_count);
}

glm::mat4 tumble_pose(int frame, int frame_count) {
    return tumble_rotation(tumble_angle(frame, frame_count)) * half_size();
}

void render_white_pixel(Framebuffer& framebuffer) {
    framebuffer.clear(kBlack);
    const OrthoCamera camera(framebuffer.width(), framebuffer.height());
    const glm::ivec2 centre = *camera.pixel_from_world({0.0F, 0.0F, 0.0F});
    framebuffer.set_pixel(centre.x, centre.y, kWhite);
}

void render_spokes(Framebuffer& framebuffer) {
    framebuffer.clear(kBlack);
    const OrthoCamera camera(framebuffer.width(), framebuffer.height());
    const glm::ivec2 centre = *camera.pixel_from_world({0.0F, 0.0F, 0.0F});
    for (int spoke = 0; spoke < kSpokeCount; ++spoke) {
        const double angle = 2.0 * std::numbers::pi * spoke / kSpokeCount;
        const glm::dvec3 tip(0.9 * std::cos(angle), 0.9 * std::sin(angle), 0.0);
        draw_line(framebuffer, centre, *camera.pixel_from_world(glm::vec3(tip)), kWhite);
    }
}

void render_cube(Framebuffer& framebuffer, const glm::mat4& pose, CubeStyle style, Rgb line_colour) {
    if (style == CubeStyle::lit) {
        Scene scene = DiaryScene("lit-cube").still(framebuffer.width(), framebuffer.height());
        scene.objects.front().model = pose;
        DepthBuffer unused;  // one convex mesh: never prepared
        render(framebuffer, scene, unused);
        return;
    }
    framebuffer.clear(kBlack);
    const OrthoCamera camera(framebuffer.width(), framebuffer.height());
    const Cube cube = Cube().posed(pose);
    switch (style) {
    case CubeStyle::filled: draw_faces(framebuffer, camera, cube, kCubeFacePalette); break;
    case CubeStyle::wireframe: draw_edges(framebuffer, camera, cube, EdgeSelection::all, line_colour); break;
    case CubeStyle::culled_wireframe:
        draw_edges(framebuffer, camera, cube, EdgeSelection::front_facing, line_colour);
        break;
    case CubeStyle::lit: break;
    }
}

void render_still_cube(Framebuffer& framebuffer, CubeStyle style) {
    render_cube(framebuffer, still_cube_pose(), style, kWhite);
}

void render_unit_cube(Framebuffer& framebuffer) {
    render_cube(framebuffer, glm::mat4(1.0F), CubeStyle::filled, kWhite);
}

void render_tumble_frame(Framebuffer& framebuffer, int frame, int frame_count, CubeStyle style) {
    render_cube(framebuffer, tumble_pose(frame, frame_count), style, kCornflowerBlue);
}

}  // namespace raster
