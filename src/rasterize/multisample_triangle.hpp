#pragma once

#include "rasterize/sample_buffer.hpp"
#include "rasterize/sample_coverage.hpp"
#include "rasterize/triangle_loop.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <glm/vec2.hpp>

// Multisampling: one triangle's coverage and depth tested at every sample position, its shader
// run once per pixel, and the colour written to the samples that passed
// (doc/conventions.md#samples). Coverage is the one-sample fill of the triangle moved by each
// sample's offset, so it keeps the fill rule and is exactly what a pass at that position covers.
namespace raster::detail {

// Draws one triangle facing the camera into rows `rows` of `target`; depth is tested per sample
// when `depth_test`, and written per sample always (a transparent frame reads coverage from it).
// The pixels go through `batch` when given (the caller flushes it), else through one of its own.
template <typename Shader, Interpolation kMode>
void shade_triangle_samples(SampleBuffer& target, bool depth_test,
                            const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, const Shader& shader,
                            PixelRect rows, std::span<const SampleOffset> offsets, LaneBatch<Shader>* batch = nullptr) {
    static_assert(kMode != Interpolation::perspective_float, "a lab choice, drawn with one sample only");
    using Varying = typename Shader::Varying;
    const std::optional<TriangleSetup<Shader>> setup = set_up_triangle(corners, shader);
    if (!setup) return;  // covers nothing
    const std::array<SubpixelPoint, 3>& points = setup->points;
    const WeightPlane& w1 = setup->w1;
    const WeightPlane& w2 = setup->w2;
    const Varying& base = setup->base;
    const Varying& along1 = setup->along1;
    const Varying& along2 = setup->along2;
    const double z0 = corners[0].depth, z1 = corners[1].depth - z0, z2 = corners[2].depth - z0;
    const double inv0 = 1.0 / corners[0].depth, inv1 = 1.0 / corners[1].depth, inv2 = 1.0 / corners[2].depth;
    const PerspectiveWeights weights(w1, w2, inv0, inv1, inv2);
    const bool constant = setup->constant;
    const Rgb constant_colour = setup->constant_colour;
    // The view depth where the weights of corners 1 and 2 are a and b.
    const auto depth_at = [&](double a, double b) {
        if constexpr (kMode == Interpolation::perspective) {
            return static_cast<float>(1.0 / ((1.0 - a - b) * inv0 + a * inv1 + b * inv2));
        } else {
            return static_cast<float>(z0 + z1 * a + z2 * b);
        }
    };
    // The Varying where the weights are a and b, as shade_triangle computes it at a pixel.
    const auto varying_at = [&](double a, double b) -> PixelVarying<Varying> {
        if constexpr (kMode == Interpolation::perspective) {
            const double q1 = a * inv1, q2 = b * inv2, sum = (1.0 - a - b) * inv0 + q1 + q2;
            return perspective_varying<Shader>(base, along1, along2, weights, q1, q2, sum, 1.0 / sum);
        } else {
            const Varying varying = base + along1 * static_cast<float>(a) + along2 * static_cast<float>(b);
            if constexpr (NeedsFootprint<Shader>) {
                const Varying step =
                    along1 * static_cast<float>(w1.per_pixel_x()) + along2 * static_cast<float>(w2.per_pixel_x());
                const Varying step_y =
                    along1 * static_cast<float>(w1.per_pixel_y()) + along2 * static_cast<float>(w2.per_pixel_y());
                return {varying, step, step_y};
            } else {
                return {varying};
            }
        }
    };
    LaneBatch<Shader> own(shader);
    LaneBatch<Shader>& lanes = batch != nullptr ? *batch : own;
    if (constant) lanes.flush();  // its pixels are written at once: earlier triangles' queued ones first

    const SampleCoverage coverage(points, offsets);
    const int count = static_cast<int>(std::min<std::size_t>(offsets.size(), kMaxSamples));
    const std::uint32_t all = coverage.all();
    coverage.rows(rows, [&](int y, int begin, int end, int inner_begin, int inner_end) {
        for (int x = begin; x < end; ++x) {
            // Inside the inner columns every sample is covered: no test per sample there.
            const std::uint32_t covered = x >= inner_begin && x < inner_end ? all : coverage.at(x, y);
            if (covered == 0) continue;
            const double a = w1.at(x, y), b = w2.at(x, y);
            target.touch(x, y);
            float* nearest = target.depths(x, y);
            std::uint32_t passed = 0;
            double sum_a = 0.0, sum_b = 0.0;
            int inside = 0;
            for (int s = 0; s < count; ++s) {
                if ((covered & (std::uint32_t{1} << s)) == 0) continue;
                const SampleOffset& o = offsets[static_cast<std::size_t>(s)];
                const double as = a + o.x * w1.per_pixel_x() + o.y * w1.per_pixel_y();
                const double bs = b + o.x * w2.per_pixel_x() + o.y * w2.per_pixel_y();
                sum_a += as, sum_b += bs, ++inside;
                const float z = depth_at(as, bs);
                if (depth_test && z > nearest[s]) continue;  // something nearer is already there
                nearest[s] = z;
                passed |= std::uint32_t{1} << s;
            }
            if (passed == 0) continue;
            if constexpr (DepthOnly<Shader>) continue;
            // Shaded once: at the centre when every sample is inside, else at the covered samples'
            // centroid, which lies inside the triangle, so nothing is read from beyond its edges.
            std::uint8_t* out = target.colours(x, y);
            if (constant) {
                write_samples(out, passed, constant_colour);
                continue;
            }
            lanes.add(out, passed, covered == all ? varying_at(a, b) : varying_at(sum_a / inside, sum_b / inside));
        }
    });
    if (batch == nullptr) lanes.flush();
}

}  // namespace raster::detail
