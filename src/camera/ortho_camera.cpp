#include <raster/camera/ortho_camera.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <glm/geometric.hpp>

namespace raster {
namespace {

void require_side(int side, const char* name) {
    if (side < 1 || side > kMaxSubpixelCoordinate) {
        throw std::invalid_argument(std::string("camera ") + name + " must be 1.." +
                                    std::to_string(kMaxSubpixelCoordinate) + " pixels, got " + std::to_string(side));
    }
}

bool is_finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

OrthoCamera::OrthoCamera(int width, int height) {
    require_side(width, "width");
    require_side(height, "height");
    scale_ = (std::min(width, height) - 1) / 2.0;
    centre_ = {(width - 1) / 2.0, (height - 1) / 2.0};
}

OrthoCamera OrthoCamera::look_at(int width, int height, glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    OrthoCamera camera(width, height);
    const glm::dvec3 from(eye);
    const glm::dvec3 to(target);
    const glm::dvec3 sky(up);
    if (!is_finite(from) || !is_finite(to) || !is_finite(sky)) {
        throw std::invalid_argument("camera eye, target and up must be finite");
    }
    const glm::dvec3 view = to - from;
    const double distance = glm::length(view);
    if (!(distance > 0.0)) throw std::invalid_argument("camera eye and target coincide");
    const glm::dvec3 forward = view / distance;
    const glm::dvec3 upright = sky - glm::dot(sky, forward) * forward;
    // Below this the up vector left after Gram-Schmidt is rounding noise: the view runs along up.
    constexpr double kParallel = 1e-9;
    if (!(glm::length(upright) > kParallel * std::max(glm::length(sky), 1e-300))) {
        throw std::invalid_argument("camera looks straight along its up direction; move the eye off that axis");
    }
    camera.eye_ = from;
    camera.forward_ = forward;
    camera.up_ = glm::normalize(upright);
    camera.right_ = glm::cross(camera.up_, camera.forward_);  // left-handed: right = up x forward
    return camera;
}

glm::dvec2 OrthoCamera::screen_from_world(glm::vec3 world) const noexcept {
    return screen_from_view(view_from_world(world));
}

std::optional<SubpixelPoint> OrthoCamera::subpixel_from_world(glm::vec3 world) const noexcept {
    return snap_to_subpixel(screen_from_world(world));
}

std::optional<glm::ivec2> OrthoCamera::pixel_from_world(glm::vec3 world) const noexcept {
    const std::optional<SubpixelPoint> snapped = subpixel_from_world(world);
    if (!snapped) return std::nullopt;
    return nearest_pixel(*snapped);
}

}  // namespace raster
