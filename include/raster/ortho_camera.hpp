#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster {

// A fixed orthographic camera: eye at (0, 0, -1) looking along +Z, +Y up, left-handed.
// World x and y in [-1, 1] fill the shorter side of the image, centred; z never moves a point
// on screen (doc/conventions.md#camera).
class OrthoCamera {
public:
    OrthoCamera(int width, int height);

    // Continuous pixel coordinates: pixel centres sit on whole numbers, y grows downward.
    [[nodiscard]] glm::dvec2 screen_from_world(glm::vec3 world) const noexcept;
    // The pixel whose centre is nearest; halves round up (toward +x and +y).
    [[nodiscard]] glm::ivec2 pixel_from_world(glm::vec3 world) const noexcept;
    // The direction the camera looks in, pointing into the scene.
    [[nodiscard]] static constexpr glm::vec3 direction() noexcept { return {0.0F, 0.0F, 1.0F}; }

    // Pixels per world unit: (min(width, height) - 1) / 2.
    [[nodiscard]] double scale() const noexcept { return scale_; }

private:
    double scale_;
    glm::dvec2 centre_;
};

// Rounds continuous pixel coordinates to the nearest pixel (halves up), clamped to a range that
// keeps later integer arithmetic exact; NaN goes to the far negative edge.
[[nodiscard]] glm::ivec2 nearest_pixel(glm::dvec2 screen) noexcept;

}  // namespace raster
