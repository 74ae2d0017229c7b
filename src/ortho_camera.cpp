#include <raster/ortho_camera.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace raster {
namespace {

void require_side(int side, const char* name) {
    if (side < 1 || side > kMaxSubpixelCoordinate) {
        throw std::invalid_argument(std::string("camera ") + name + " must be 1.." +
                                    std::to_string(kMaxSubpixelCoordinate) + " pixels, got " +
                                    std::to_string(side));
    }
}

}  // namespace

OrthoCamera::OrthoCamera(int width, int height) {
    require_side(width, "width");
    require_side(height, "height");
    scale_ = (std::min(width, height) - 1) / 2.0;
    centre_ = {(width - 1) / 2.0, (height - 1) / 2.0};
}

glm::dvec2 OrthoCamera::screen_from_world(glm::vec3 world) const noexcept {
    return {centre_.x + scale_ * world.x, centre_.y - scale_ * world.y};
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
