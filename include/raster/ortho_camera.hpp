#pragma once

#include <raster/subpixel.hpp>

#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster {

// A fixed orthographic camera: eye at (0, 0, -1) looking along +Z, +Y up, left-handed.
// World x and y in [-1, 1] fill the shorter side of the image, centred; z never moves a point
// on screen (doc/conventions.md#camera).
class OrthoCamera {
public:
    // The image size in pixels; throws std::invalid_argument unless both are 1..kMaxSubpixelCoordinate.
    OrthoCamera(int width, int height);

    // Continuous pixel coordinates: pixel centres sit on whole numbers, y grows downward.
    [[nodiscard]] glm::dvec2 screen_from_world(glm::vec3 world) const noexcept;
    // The screen position snapped to the subpixel grid the fill works on; nothing if not finite
    // or too far away.
    [[nodiscard]] std::optional<SubpixelPoint> subpixel_from_world(glm::vec3 world) const noexcept;
    // The pixel whose centre is nearest the snapped position (halves round up).
    [[nodiscard]] std::optional<glm::ivec2> pixel_from_world(glm::vec3 world) const noexcept;
    // The direction the camera looks in, pointing into the scene.
    [[nodiscard]] static constexpr glm::vec3 direction() noexcept { return {0.0F, 0.0F, 1.0F}; }

    // Pixels per world unit: (min(width, height) - 1) / 2.
    [[nodiscard]] double scale() const noexcept { return scale_; }

private:
    double scale_ = 0.0;
    glm::dvec2 centre_{};
};

}  // namespace raster
