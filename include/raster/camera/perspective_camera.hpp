#pragma once

#include <raster/camera/ortho_camera.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raster {

// A pinhole camera with perspective projection, left-handed with +Y up like OrthoCamera
// (doc/conventions.md#perspective). Clip space is x_c = x_v / (a tan(fov/2)), y_c = y_v / tan(fov/2),
// z_c = far (z_v - near) / (far - near), w_c = z_v for view coordinates (x_v right, y_v up, z_v
// ahead) and aspect a = width / height; so NDC depth runs from 0 at the near plane to 1 at the far one.
// The viewport follows OpenGL and Vulkan: NDC x = -1 at the left edge of the first pixel column
// and +1 at the right edge of the last, y = +1 at the top edge; with pixel centres on whole
// numbers, screen x = (x_ndc + 1) W / 2 - 1/2 and y = (1 - y_ndc) H / 2 - 1/2.
class PerspectiveCamera {
public:
    struct Lens {
        double fov_y_degrees = 60.0;  // vertical field of view, 0 < fov < 180
        double near = 0.1;            // distance to the near plane, 1e-18 or more
        double far = 100.0;           // distance to the far plane, > near, 1e18 at most
    };

    // Throws std::invalid_argument for sizes outside 1..kMaxSubpixelCoordinate, a lens out of
    // range, non-finite vectors, the eye on the target, or a view along `up`.
    [[nodiscard]] static PerspectiveCamera look_at(int width, int height, glm::vec3 eye, glm::vec3 target, glm::vec3 up,
                                                   Lens lens);
    // raster-engine's first-person form: yaw turns from +Z toward +X about +Y, pitch raises the
    // view toward +Y; both in radians, |pitch| < pi/2 (within about 1e-9 of it the view runs
    // along +Y and look_at refuses it).
    // Looks along an orthographic camera's axes from its eye, bit for bit.
    [[nodiscard]] static PerspectiveCamera from_view(const OrthoCamera& view, int width, int height, Lens lens) {
        return {view, width, height, lens};
    }
    [[nodiscard]] static PerspectiveCamera first_person(int width, int height, glm::vec3 eye, double pitch, double yaw,
                                                        Lens lens);

    [[nodiscard]] glm::dvec3 view_from_world(glm::vec3 world) const noexcept { return view_.view_from_world(world); }
    // Inline, as view_from_world is: each point of a cloud is projected on its own.
    [[nodiscard]] glm::dvec4 clip_from_view(glm::dvec3 view) const noexcept {
        const double depth_scale = lens_.far / (lens_.far - lens_.near);
        return {view.x * x_scale_, view.y * y_scale_, (view.z - lens_.near) * depth_scale, view.z};
    }
    [[nodiscard]] glm::dvec4 clip_from_world(glm::vec3 world) const noexcept {
        return clip_from_view(view_from_world(world));
    }
    // Continuous pixel coordinates of a clip-space point in front of the eye (w > 0).
    [[nodiscard]] glm::dvec2 screen_from_clip(glm::dvec4 clip) const noexcept {
        const double x_ndc = clip.x / clip.w, y_ndc = clip.y / clip.w;
        return {(x_ndc + 1.0) * width_ / 2.0 - 0.5 - offset_.x, (1.0 - y_ndc) * height_ / 2.0 - 0.5 - offset_.y};
    }

    [[nodiscard]] glm::vec3 eye() const noexcept { return view_.eye(); }
    [[nodiscard]] glm::vec3 direction() const noexcept { return view_.direction(); }
    [[nodiscard]] const Lens& lens() const noexcept { return lens_; }
    // The same camera shifted so that each pixel centre sees what lies `offset` pixels from it
    // (x right, y down): one sample position of an anti-aliased frame (raster/render/samples.hpp).
    [[nodiscard]] PerspectiveCamera sampled_at(glm::dvec2 offset) const noexcept {
        PerspectiveCamera shifted = *this;
        shifted.offset_ += offset;
        return shifted;
    }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

private:
    PerspectiveCamera(OrthoCamera view, int width, int height, Lens lens);

    OrthoCamera view_;  // the eye and its axes: the same look-at rules and errors
    int width_;
    int height_;
    Lens lens_;
    double x_scale_;               // 1 / (aspect tan(fov/2))
    double y_scale_;               // 1 / tan(fov/2)
    glm::dvec2 offset_{0.0, 0.0};  // the sample position, in pixels from the centre
};

// A pinhole of vertical field of view `fov_degrees` (0 < fov < 180) matching an orthographic
// camera: the eye moves back along its line of sight until the plane through the world origin
// keeps the orthographic framing, so a small field of view looks like the orthographic picture
// and a wide one is seen from close by. Near and far are 1/100 of that distance and 100 beyond
// it. Throws std::invalid_argument for a field of view out of range or an eye too far out to move.
[[nodiscard]] PerspectiveCamera perspective_matching(const OrthoCamera& flat, int width, int height,
                                                     double fov_degrees);

}  // namespace raster
