#pragma once

#include <raster/camera/perspective_camera.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// perspective-lab's frame and floor, shared by its three measures.
namespace perspective_lab {

inline constexpr int kWidth = 800, kHeight = 600;

inline raster::PerspectiveCamera grazing_camera(double degrees) {
    return raster::PerspectiveCamera::first_person(kWidth, kHeight, {0, 0, 0}, -degrees * std::numbers::pi / 180.0, 0.0,
                                                   {60.0, 0.1, 100.0});
}

// The floor point seen at screen point (x, y) (pixel (i, j) has its centre at i + 0.5, j + 0.5),
// or nothing above the horizon.
inline std::optional<glm::dvec2> floor_at_point(const raster::PerspectiveCamera& camera, double x, double y) {
    // Invert the viewport and projection: a direction in view space, then in the world.
    const double t = std::tan(camera.lens().fov_y_degrees * std::numbers::pi / 360.0);
    const double x_ndc = x * 2.0 / kWidth - 1.0, y_ndc = 1.0 - y * 2.0 / kHeight;
    const glm::dvec3 forward(camera.direction());
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), forward));
    const glm::dvec3 up = glm::cross(forward, right);
    const glm::dvec3 ray = forward + right * (x_ndc * t * kWidth / kHeight) + up * (y_ndc * t);
    if (!(ray.y < 0.0)) return std::nullopt;
    const double s = -1.0 / ray.y;  // from the eye at the origin down to y = -1
    return glm::dvec2(ray.x * s, ray.z * s);
}

inline std::optional<glm::dvec2> floor_at(const raster::PerspectiveCamera& camera, int i, int j) {
    return floor_at_point(camera, i + 0.5, j + 0.5);
}

}  // namespace perspective_lab
