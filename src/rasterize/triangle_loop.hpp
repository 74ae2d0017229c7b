#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/image/subpixel.hpp>
#include <raster/rasterize/depth_buffer.hpp>
#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/shader.hpp>

#include "rasterize/depth_only.hpp"
#include "rasterize/lane_batch.hpp"
#include "rasterize/perspective_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <optional>

// The triangle loop behind every shader and both front ends: exact coverage from
// rasterize_convex, attributes interpolated linearly in screen space or through 1/w.
namespace raster::detail {

// View depths beyond this (world units) are refused, so that depth arithmetic stays finite.
inline constexpr double kMaxViewDepth = 1e18;

// How a view depth is kept: the product stores the float itself; the lab also tries fixed-point
// codes (kept in the same float buffer, exact up to 24 bits).
struct FloatDepth {
    [[nodiscard]] float operator()(float depth) const noexcept { return depth; }
};

template <typename Varying>
struct ShadedCorner {
    SubpixelPoint at;
    float depth;
    Varying varying;
};

// Weights of corners 1 and 2: w1 = ((P - p0) x b) / (a x b), w2 = (a x (P - p0)) / (a x b),
// with a = p1 - p0 and b = p2 - p0; a x b is the exact twice_signed_area, never zero here.
inline std::array<WeightPlane, 2> weight_planes(SubpixelPoint p0, SubpixelPoint p1, SubpixelPoint p2,
                                                std::int64_t twice_area) noexcept {
    const double x0 = p0.x, y0 = p0.y;
    const double ax = p1.x - x0, ay = p1.y - y0, bx = p2.x - x0, by = p2.y - y0;
    const auto cross = static_cast<double>(twice_area);
    return {WeightPlane{x0, y0, by / cross, -bx / cross}, WeightPlane{x0, y0, -ay / cross, ax / cross}};
}

// How attributes vary across the screen: linearly for an orthographic view; through 1/w for a
// perspective one, where each corner's depth is its view depth w > 0. The lab also tries the
// perspective weights in float (perspective_float) against the product's double.
enum class Interpolation { screen_linear, perspective, perspective_float };

// What every pixel of one triangle shares: the screen weights of corners 1 and 2, the Varying
// at corner 0 and along both edges, and the colour of a triangle shaded the same everywhere.
template <typename Shader>
struct TriangleSetup {
    using Varying = typename Shader::Varying;
    std::array<SubpixelPoint, 3> points;
    WeightPlane w1;
    WeightPlane w2;
    Varying base;
    Varying along1;
    Varying along2;
    bool constant = false;
    Rgb constant_colour{};
};

// Nothing for a triangle that covers nothing (its weights would divide by zero).
template <typename Shader>
std::optional<TriangleSetup<Shader>> triangle_weights(
    const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners) {
    const std::array<SubpixelPoint, 3> points{corners[0].at, corners[1].at, corners[2].at};
    const std::int64_t twice_area = twice_signed_area(points);
    if (twice_area == 0) return std::nullopt;
    const std::array<WeightPlane, 2> planes = weight_planes(points[0], points[1], points[2], twice_area);
    return TriangleSetup<Shader>{points,
                                 planes[0],
                                 planes[1],
                                 corners[0].varying,
                                 corners[1].varying - corners[0].varying,
                                 corners[2].varying - corners[0].varying};
}

// triangle_weights(), and the colour of a triangle shaded the same everywhere.
template <typename Shader>
std::optional<TriangleSetup<Shader>> set_up_triangle(
    const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, const Shader& shader) {
    std::optional<TriangleSetup<Shader>> setup = triangle_weights<Shader>(corners);
    // A Varying equal at all three corners (flat shading) is the same at every pixel: shaded
    // once here, the pixels only take depth and the write. The colour is the one pixel() would give.
    if constexpr (!NeedsFootprint<Shader> && std::equality_comparable<typename Shader::Varying>) {
        if (setup) {
            setup->constant = corners[1].varying == setup->base && corners[2].varying == setup->base;
            if (setup->constant) setup->constant_colour = shader.pixel(setup->base);
        }
    }
    return setup;
}

// An orthographic triangle: Varying and depth step linearly along each span.
template <typename Shader, typename DepthFormat>
void fill_screen_linear(const TriangleSetup<Shader>& setup,
                        const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, Framebuffer& colour,
                        DepthBuffer* depth, const PixelRect& clip, DepthFormat stored, LaneBatch<Shader>& lanes) {
    using Varying = typename Shader::Varying;
    const WeightPlane& w1 = setup.w1;  // not a structured binding: clang 14 cannot capture those
    const WeightPlane& w2 = setup.w2;
    const Varying step =
        setup.along1 * static_cast<float>(w1.per_pixel_x()) + setup.along2 * static_cast<float>(w2.per_pixel_x());
    const Varying step_y =
        setup.along1 * static_cast<float>(w1.per_pixel_y()) + setup.along2 * static_cast<float>(w2.per_pixel_y());
    const double z0 = corners[0].depth;
    const double z1 = corners[1].depth - z0, z2 = corners[2].depth - z0;
    const auto z_step = static_cast<float>(z1 * w1.per_pixel_x() + z2 * w2.per_pixel_x());
    std::uint8_t* const pixels = colour.pixels();
    const std::size_t width = static_cast<std::size_t>(colour.width());
    rasterize_convex(setup.points, clip, [&](Span span) {
        const double i = span.x_begin, j = span.y;
        const double a = w1.at(i, j), b = w2.at(i, j);
        Varying varying = setup.base + setup.along1 * static_cast<float>(a) + setup.along2 * static_cast<float>(b);
        const auto z_start = static_cast<float>(z0 + z1 * a + z2 * b);
        std::uint8_t* out =
            pixels + (static_cast<std::size_t>(span.y) * width + static_cast<std::size_t>(span.x_begin)) * 3;
        float* nearest = depth != nullptr ? depth->row(span.y) + span.x_begin : nullptr;
        for (int k = 0; k < span.x_end - span.x_begin; ++k, out += 3, varying = varying + step) {
            if (nearest != nullptr) {
                const float z = stored(z_start + z_step * static_cast<float>(k));
                if (z > nearest[k]) continue;  // something nearer is already there
                nearest[k] = z;
            }
            if constexpr (DepthOnly<Shader>) continue;
            if (setup.constant) {
                out[0] = setup.constant_colour.r, out[1] = setup.constant_colour.g, out[2] = setup.constant_colour.b;
                continue;
            }
            lanes.add(out, 1, {varying, step, step_y});  // the steps are constant across the triangle
        }
    });
}

// A perspective triangle: screen weights a, b of corners 1 and 2 become b_k / w_k over their
// sum, the weights of the surface point seen there; the sum is 1 / w, so the view depth comes
// with them.
template <typename Shader, typename DepthFormat, PerspectiveRun::Precision kPrecision>
void fill_perspective(const TriangleSetup<Shader>& setup,
                      const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, Framebuffer& colour,
                      DepthBuffer* depth, const PixelRect& clip, DepthFormat stored, LaneBatch<Shader>& lanes) {
    const WeightPlane& w1 = setup.w1;
    const WeightPlane& w2 = setup.w2;
    const double inv0 = 1.0 / corners[0].depth, inv1 = 1.0 / corners[1].depth, inv2 = 1.0 / corners[2].depth;
    const PerspectiveWeights weights(w1, w2, inv0, inv1, inv2);
    constexpr auto kNeed = NeedsFootprint<Shader> ? PerspectiveRun::Need::footprint : PerspectiveRun::Need::weights;
    std::uint8_t* const pixels = colour.pixels();
    const std::size_t width = static_cast<std::size_t>(colour.width());
    rasterize_convex(setup.points, clip, [&](Span span) {
        std::uint8_t* out =
            pixels + (static_cast<std::size_t>(span.y) * width + static_cast<std::size_t>(span.x_begin)) * 3;
        float* nearest = depth != nullptr ? depth->row(span.y) + span.x_begin : nullptr;
        if (setup.constant || DepthOnly<Shader>) {
            // Depth and one colour: a pixel at a time is quickest, the spans being short.
            for (int x = span.x_begin; x < span.x_end; ++x, out += 3) {
                if (nearest != nullptr) {
                    const double a = w1.at(x, span.y), b = w2.at(x, span.y);
                    const float z = stored(static_cast<float>(1.0 / ((1.0 - a - b) * inv0 + a * inv1 + b * inv2)));
                    if (z > nearest[x - span.x_begin]) continue;  // something nearer is already there
                    nearest[x - span.x_begin] = z;
                }
                if constexpr (!DepthOnly<Shader>) {
                    out[0] = setup.constant_colour.r, out[1] = setup.constant_colour.g,
                    out[2] = setup.constant_colour.b;
                }
            }
            return;
        }
        PerspectiveRun run;
        for (int x = span.x_begin; x < span.x_end; x += PerspectiveRun::kSize) {
            run.compute<kNeed, kPrecision>(weights, x, span.y);
            const auto n = static_cast<std::size_t>(std::min(PerspectiveRun::kSize, span.x_end - x));
            for (std::size_t k = 0; k < n; ++k, out += 3) {
                if (nearest != nullptr) {
                    const float z = stored(run.depth[k]);
                    float& there = nearest[static_cast<std::size_t>(x - span.x_begin) + k];
                    if (z > there) continue;  // something nearer is already there
                    there = z;
                }
                lanes.add(out, 1, run.varying<Shader>(k, setup.base, setup.along1, setup.along2));
            }
        }
    });
}

// Fills one triangle facing the camera. Corner 0 anchors the interpolation, so equal corners
// give that value exactly. `rows`, when given, limits the writes to a band of rows: one strip
// of a render in strips. The pixels go through `batch` when given (the caller flushes it), else
// through one of its own.
template <typename Shader, typename DepthFormat = FloatDepth, Interpolation kMode = Interpolation::screen_linear>
void shade_triangle(Framebuffer& colour, DepthBuffer* depth,
                    const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, const Shader& shader,
                    DepthFormat stored = {}, std::optional<PixelRect> rows = std::nullopt,
                    LaneBatch<Shader>* batch = nullptr) {
    const std::optional<TriangleSetup<Shader>> setup = set_up_triangle(corners, shader);
    if (!setup) return;
    const PixelRect clip = rows.value_or(PixelRect{0, 0, colour.width(), colour.height()});
    LaneBatch<Shader> own(shader);
    LaneBatch<Shader>& lanes = batch != nullptr ? *batch : own;
    if (setup->constant) lanes.flush();  // its pixels are written at once: earlier triangles' queued ones first
    if constexpr (kMode == Interpolation::screen_linear) {
        fill_screen_linear(*setup, corners, colour, depth, clip, stored, lanes);
    } else if constexpr (kMode == Interpolation::perspective) {
        fill_perspective<Shader, DepthFormat, PerspectiveRun::Precision::double_>(*setup, corners, colour, depth, clip,
                                                                                  stored, lanes);
    } else {
        fill_perspective<Shader, DepthFormat, PerspectiveRun::Precision::single>(*setup, corners, colour, depth, clip,
                                                                                 stored, lanes);
    }
    if (batch == nullptr) lanes.flush();
}

}  // namespace raster::detail
