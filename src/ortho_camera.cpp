#include <raster/ortho_camera.hpp>

#include <raster/fill.hpp>

#include <algorithm>
#include <cmath>

namespace raster {
namespace {

int nearest_whole(double value) {
    constexpr double limit = kMaxFillCoordinate;
    if (!(value > -limit)) return -kMaxFillCoordinate;  // also catches NaN
    if (value > limit) return kMaxFillCoordinate;
    return static_cast<int>(std::floor(value + 0.5));
}

}  // namespace

OrthoCamera::OrthoCamera(int width, int height)
    : scale_((std::min(width, height) - 1) / 2.0),
      centre_((width - 1) / 2.0, (height - 1) / 2.0) {}

glm::dvec2 OrthoCamera::screen_from_world(glm::vec3 world) const noexcept {
    return {centre_.x + scale_ * world.x, centre_.y - scale_ * world.y};
}

glm::ivec2 OrthoCamera::pixel_from_world(glm::vec3 world) const noexcept {
    return nearest_pixel(screen_from_world(world));
}

glm::ivec2 nearest_pixel(glm::dvec2 screen) noexcept {
    return {nearest_whole(screen.x), nearest_whole(screen.y)};
}

}  // namespace raster
