#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/camera/perspective_camera.hpp>

#include "rasterize/triangle_loop.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <glm/vec3.hpp>

// Points and segment ends taken to the screen for splats and lines, by either camera, and the
// depth rule that keeps them in front of the surface they lie on (doc/conventions.md#points-and-lines).
namespace raster::detail {

struct ScreenPoint {
    double x;  // continuous pixel coordinates, pixel centres on whole numbers
    double y;
    double depth;  // view depth
};

// A segment's visible part on screen, and where its ends lie along the whole segment (0 to 1).
struct ScreenSegment {
    ScreenPoint a;
    ScreenPoint b;
    double t_a;
    double t_b;
};

inline bool finite_on_screen(const ScreenPoint& p) noexcept {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::abs(p.depth) <= kMaxViewDepth;
}

// Depth is moved toward the viewer by the world size of `pixels` pixels at that depth: a splat
// is tested as the sphere it stands for, so a surface under it sloping up to 45 degrees stays behind.
template <typename Camera>
class PointProjection;

template <>
class PointProjection<OrthoCamera> {
public:
    static constexpr bool kPerspective = false;
    explicit PointProjection(const OrthoCamera& camera) noexcept : camera_(camera) {}

    [[nodiscard]] std::optional<ScreenPoint> point(glm::vec3 world) const noexcept {
        const glm::dvec3 view = camera_.view_from_world(world);
        const glm::dvec2 at = camera_.screen_from_view(view);
        const ScreenPoint p{at.x, at.y, view.z};
        return finite_on_screen(p) ? std::optional(p) : std::nullopt;
    }
    [[nodiscard]] std::optional<ScreenSegment> segment(glm::vec3 a, glm::vec3 b) const noexcept {
        const std::optional<ScreenPoint> pa = point(a), pb = point(b);
        if (!pa || !pb) return std::nullopt;
        return ScreenSegment{*pa, *pb, 0.0, 1.0};
    }
    [[nodiscard]] float nearer(double depth, double pixels) const noexcept {
        return static_cast<float>(camera_.scale() > 0.0 ? depth - pixels / camera_.scale() : depth);
    }

private:
    const OrthoCamera& camera_;
};

template <>
class PointProjection<PerspectiveCamera> {
public:
    static constexpr bool kPerspective = true;
    explicit PointProjection(const PerspectiveCamera& camera) noexcept
        : camera_(camera),
          pixel_at_one_(2.0 * std::tan(camera.lens().fov_y_degrees * std::numbers::pi / 360.0) / camera.height()) {}

    // Nothing for a point outside the near and far planes, which cut surfaces too.
    [[nodiscard]] std::optional<ScreenPoint> point(glm::vec3 world) const noexcept {
        const glm::dvec4 clip = camera_.clip_from_world(world);
        if (!(clip.w >= camera_.lens().near && clip.w <= camera_.lens().far)) return std::nullopt;
        return on_screen(clip);
    }
    // The part of a segment between the near and far planes.
    [[nodiscard]] std::optional<ScreenSegment> segment(glm::vec3 a, glm::vec3 b) const noexcept {
        const glm::dvec4 ca = camera_.clip_from_world(a), cb = camera_.clip_from_world(b);
        double t0 = 0.0, t1 = 1.0;
        if (!cut(ca.w - camera_.lens().near, cb.w - camera_.lens().near, t0, t1)) return std::nullopt;
        if (!cut(camera_.lens().far - ca.w, camera_.lens().far - cb.w, t0, t1)) return std::nullopt;
        const std::optional<ScreenPoint> pa = on_screen(ca + (cb - ca) * t0), pb = on_screen(ca + (cb - ca) * t1);
        if (!pa || !pb) return std::nullopt;
        return ScreenSegment{*pa, *pb, t0, t1};
    }
    [[nodiscard]] float nearer(double depth, double pixels) const noexcept {
        return static_cast<float>(depth * std::max(1.0 - pixels * pixel_at_one_, 0.5));
    }

private:
    [[nodiscard]] std::optional<ScreenPoint> on_screen(const glm::dvec4& clip) const noexcept {
        const glm::dvec2 at = camera_.screen_from_clip(clip);
        const ScreenPoint p{at.x, at.y, clip.w};
        return finite_on_screen(p) ? std::optional(p) : std::nullopt;
    }
    // Narrows [t0, t1] to where the linear function from `from` to `to` is at least 0.
    static bool cut(double from, double to, double& t0, double& t1) noexcept {
        if (!(from >= 0.0) && !(to >= 0.0)) return false;
        if (from < 0.0) t0 = std::max(t0, from / (from - to));
        if (to < 0.0) t1 = std::min(t1, from / (from - to));
        return t0 <= t1;
    }

    const PerspectiveCamera& camera_;
    double pixel_at_one_;  // world units a pixel spans at view depth 1
};

}  // namespace raster::detail
