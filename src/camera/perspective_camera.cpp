#include <raster/camera/perspective_camera.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <glm/geometric.hpp>

namespace raster {

PerspectiveCamera::PerspectiveCamera(OrthoCamera view, int width, int height, Lens lens)
    : view_(view), width_(width), height_(height), lens_(lens) {
    static_cast<void>(OrthoCamera(width, height));  // the same size limits, with the same errors
    if (!(lens.fov_y_degrees > 0.0 && lens.fov_y_degrees < 180.0)) {
        throw std::invalid_argument("field of view must be between 0 and 180 degrees, got " +
                                    std::to_string(lens.fov_y_degrees));
    }
    // Within these, view depths stay normal floats and their reciprocals finite.
    constexpr double kNearest = 1e-18, kFarthest = 1e18;
    if (!(lens.near >= kNearest && lens.far > lens.near && lens.far <= kFarthest)) {
        throw std::invalid_argument("near and far must satisfy 1e-18 <= near < far <= 1e18, got near " +
                                    std::to_string(lens.near) + " and far " + std::to_string(lens.far));
    }
    const double half_angle = lens.fov_y_degrees * std::numbers::pi / 360.0;
    y_scale_ = 1.0 / std::tan(half_angle);
    x_scale_ = y_scale_ * height / width;
}

PerspectiveCamera PerspectiveCamera::look_at(int width, int height, glm::vec3 eye, glm::vec3 target, glm::vec3 up,
                                             Lens lens) {
    return {OrthoCamera::look_at(width, height, eye, target, up), width, height, lens};
}

PerspectiveCamera PerspectiveCamera::first_person(int width, int height, glm::vec3 eye, double pitch, double yaw,
                                                  Lens lens) {
    if (!(std::abs(pitch) < std::numbers::pi / 2) || !std::isfinite(yaw)) {
        throw std::invalid_argument("pitch must be strictly between -pi/2 and pi/2 and yaw finite");
    }
    const glm::dvec3 ahead{std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
    // A target as far off as the eye itself, so that the direction survives rounding to float.
    const glm::dvec3 target = glm::dvec3(eye) + ahead * std::max(1.0, glm::length(glm::dvec3(eye)));
    return look_at(width, height, eye, glm::vec3(target), {0.0F, 1.0F, 0.0F}, lens);
}

PerspectiveCamera perspective_matching(const OrthoCamera& flat, int width, int height, double fov_degrees) {
    if (!(fov_degrees > 0.0 && fov_degrees < 180.0)) {
        throw std::invalid_argument("field of view must be between 0 and 180 degrees, got " +
                                    std::to_string(fov_degrees));
    }
    const double to_origin = flat.view_from_world(glm::vec3(0.0F)).z;
    // Pixels per world unit match the orthographic camera's on the plane through the origin.
    const double half_angle = fov_degrees * std::numbers::pi / 360.0;
    const double distance = height / (2.0 * std::max(flat.scale(), 0.5) * std::tan(half_angle));
    const PerspectiveCamera::Lens lens{fov_degrees, distance / 100.0, distance + 100.0};
    // The same axes, the eye moved in double precision: no rounding through floats on the way.
    const OrthoCamera moved = flat.dollied(to_origin - distance);
    if (!std::isfinite(glm::length(glm::dvec3(moved.eye()))))
        throw std::invalid_argument("camera eye is too far out to move back");
    return PerspectiveCamera::from_view(moved, width, height, lens);
}

}  // namespace raster
