#pragma once

#include <raster/image/subpixel.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <glm/vec4.hpp>

// Clipping in homogeneous clip space (doc/conventions.md#clipping): Sutherland-Hodgman against
// the near and far planes and a guard band in x and y, every attribute interpolated linearly in
// clip space, where it is linear.
namespace raster::detail {

template <typename Varying>
struct ClipVertex {
    glm::dvec4 clip;
    Varying varying;
};

// A triangle cut by six planes has at most nine corners; the room to spare absorbs rounding.
inline constexpr std::size_t kMaxClippedCorners = 16;

template <typename Varying>
struct ClippedPolygon {
    std::array<ClipVertex<Varying>, kMaxClippedCorners> corners{};
    std::size_t size = 0;
};

// The guard band: x and y are clipped this many pixels beyond the image's edges, so that
// projected positions stay well inside the exact fill's range for any image up to 2^20 px.
inline constexpr double kGuardBandPixels = kMaxSubpixelCoordinate / 4.0;

// Inside means plane . clip >= 0.
struct ClipPlanes {
    std::array<glm::dvec4, 6> planes;

    // Near: z_c >= 0; far: z_c <= w_c; x and y within `band` pixels beyond the edges of a
    // width x height image (the lab sets it to 0 to clip all six planes at the image).
    ClipPlanes(int width, int height, double band = kGuardBandPixels) noexcept {
        const double gx = 1.0 + 2.0 * band / width, gy = 1.0 + 2.0 * band / height;
        planes = {glm::dvec4{0, 0, 1, 0},   glm::dvec4{0, 0, -1, 1}, glm::dvec4{1, 0, 0, gx},
                  glm::dvec4{-1, 0, 0, gx}, glm::dvec4{0, 1, 0, gy}, glm::dvec4{0, -1, 0, gy}};
    }
    [[nodiscard]] static double distance(const glm::dvec4& plane, const glm::dvec4& clip) noexcept {
        return plane.x * clip.x + plane.y * clip.y + plane.z * clip.z + plane.w * clip.w;
    }
    [[nodiscard]] bool inside_all(const glm::dvec4& clip) const noexcept {
        for (const glm::dvec4& plane : planes) {
            if (!(distance(plane, clip) >= 0.0)) return false;  // NaN counts as outside
        }
        return true;
    }
};

// The part of triangle (a, b, c) inside every plane, as a convex polygon in the same winding;
// empty when nothing is inside. A vertex with NaN coordinates makes the whole triangle empty.
template <typename Varying>
ClippedPolygon<Varying> clip_triangle(const ClipPlanes& frustum, const ClipVertex<Varying>& a,
                                      const ClipVertex<Varying>& b, const ClipVertex<Varying>& c) {
    ClippedPolygon<Varying> polygon;
    polygon.corners[0] = a, polygon.corners[1] = b, polygon.corners[2] = c;
    polygon.size = 3;
    if (frustum.inside_all(a.clip) && frustum.inside_all(b.clip) && frustum.inside_all(c.clip)) return polygon;
    for (const glm::dvec4& plane : frustum.planes) {
        ClippedPolygon<Varying> kept;
        for (std::size_t i = 0; i < polygon.size; ++i) {
            const ClipVertex<Varying>& from = polygon.corners[i];
            const ClipVertex<Varying>& to = polygon.corners[(i + 1) % polygon.size];
            const double d_from = ClipPlanes::distance(plane, from.clip), d_to = ClipPlanes::distance(plane, to.clip);
            if (std::isnan(d_from) || std::isnan(d_to) || kept.size + 2 > kMaxClippedCorners) return {};
            if (d_from >= 0.0) kept.corners[kept.size++] = from;
            if ((d_from >= 0.0) != (d_to >= 0.0)) {  // the edge crosses the plane: keep the crossing
                // Measured from the inside end, so both facets sharing the edge get the same point.
                const bool from_inside = d_from >= 0.0;
                const ClipVertex<Varying>& in = from_inside ? from : to;
                const ClipVertex<Varying>& out = from_inside ? to : from;
                const double d_in = from_inside ? d_from : d_to, d_out = from_inside ? d_to : d_from;
                const double t = d_in / (d_in - d_out);
                kept.corners[kept.size++] = {in.clip + t * (out.clip - in.clip),
                                             in.varying + (out.varying - in.varying) * static_cast<float>(t)};
            }
        }
        polygon = kept;
        if (polygon.size < 3) return {};
    }
    return polygon;
}

}  // namespace raster::detail
