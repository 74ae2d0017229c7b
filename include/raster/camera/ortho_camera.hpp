#pragma once

#include <raster/image/subpixel.hpp>

#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster {

// An orthographic look-at camera, left-handed with +Y up (doc/conventions.md#camera). World
// x and y in [-1, 1] of the view fill the shorter side of the image, centred; depth along the
// view direction never moves a point on screen. The default looks from (0, 0, -1) along +Z.
class OrthoCamera {
public:
    // The image size in pixels; throws std::invalid_argument unless both are 1..kMaxSubpixelCoordinate.
    OrthoCamera(int width, int height);

    // Looks from `eye` at `target`, keeping `up` up (Gram-Schmidt). Throws std::invalid_argument
    // when a vector is not finite, the eye is on the target, or the view runs along `up`.
    [[nodiscard]] static OrthoCamera look_at(int width, int height, glm::vec3 eye,
                                             glm::vec3 target = {0.0F, 0.0F, 0.0F}, glm::vec3 up = {0.0F, 1.0F, 0.0F});

    // View coordinates: x right, y up, z the distance in front of the eye along direction().
    // Inline: every vertex and every point of a cloud passes through it. Written out so that a
    // zero component contributes exactly nothing: the default camera keeps world x and y bit for bit.
    [[nodiscard]] glm::dvec3 view_from_world(glm::vec3 world) const noexcept {
        const glm::dvec3 d = glm::dvec3(world) - eye_;
        return {right_.x * d.x + right_.y * d.y + right_.z * d.z, up_.x * d.x + up_.y * d.y + up_.z * d.z,
                forward_.x * d.x + forward_.y * d.y + forward_.z * d.z};
    }
    // The world point at a screen position and view depth: the inverse of the two maps above.
    [[nodiscard]] glm::dvec3 world_from_screen(glm::dvec2 screen, double depth) const noexcept {
        // A one-pixel side has scale 0: every screen position there is the view's centre.
        const double x = scale_ > 0.0 ? (screen.x - centre_.x) / scale_ : 0.0;
        const double y = scale_ > 0.0 ? (centre_.y - screen.y) / scale_ : 0.0;
        return eye_ + x * right_ + y * up_ + depth * forward_;
    }
    // Continuous pixel coordinates: pixel centres sit on whole numbers, y grows downward.
    [[nodiscard]] glm::dvec2 screen_from_view(glm::dvec3 view) const noexcept {
        return {centre_.x + scale_ * view.x, centre_.y - scale_ * view.y};
    }
    [[nodiscard]] glm::dvec2 screen_from_world(glm::vec3 world) const noexcept;
    // The screen position snapped to the subpixel grid the fill works on; nothing if not finite
    // or too far away.
    [[nodiscard]] std::optional<SubpixelPoint> subpixel_from_world(glm::vec3 world) const noexcept;
    // The pixel whose centre is nearest the snapped position (halves round up).
    [[nodiscard]] std::optional<glm::ivec2> pixel_from_world(glm::vec3 world) const noexcept;
    // The unit direction the camera looks in, pointing into the scene.
    [[nodiscard]] glm::vec3 direction() const noexcept { return glm::vec3(forward_); }
    [[nodiscard]] glm::vec3 eye() const noexcept { return glm::vec3(eye_); }
    [[nodiscard]] glm::vec3 up() const noexcept { return glm::vec3(up_); }
    // The same camera with its eye moved `distance` along its view, all in double precision.
    [[nodiscard]] OrthoCamera dollied(double distance) const noexcept {
        OrthoCamera moved = *this;
        moved.eye_ += distance * forward_;
        return moved;
    }

    // The same camera shifted so that each pixel centre sees what lies `offset` pixels from it
    // (x right, y down): one sample position of an anti-aliased frame (raster/render/samples.hpp).
    [[nodiscard]] OrthoCamera sampled_at(glm::dvec2 offset) const noexcept {
        OrthoCamera shifted = *this;
        shifted.centre_ -= offset;
        return shifted;
    }

    // Pixels per world unit: (min(width, height) - 1) / 2.
    [[nodiscard]] double scale() const noexcept { return scale_; }

private:
    double scale_ = 0.0;
    glm::dvec2 centre_{};
    glm::dvec3 eye_{0.0, 0.0, -1.0};
    glm::dvec3 right_{1.0, 0.0, 0.0};
    glm::dvec3 up_{0.0, 1.0, 0.0};
    glm::dvec3 forward_{0.0, 0.0, 1.0};
};

}  // namespace raster
