#pragma once

#include <raster/rasterize/depth_buffer.hpp>

#include "rasterize/fragment_list.hpp"
#include "rasterize/lane_batch.hpp"
#include "rasterize/perspective_run.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/sample_coverage.hpp"
#include "rasterize/triangle_loop.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

// A triangle whose alpha matters, its coverage and depth tested at every sample as multisampling
// does (doc/conventions.md#transparency): a blended one against the opaque depths only, which it
// leaves alone, each pixel it reaches kept as a fragment (colour, alpha, depth, samples) for the
// strip's resolve; a masked one drawn as an opaque one is, at the samples whose alpha reaches the cutoff.
namespace raster::detail {

// Where the fragment loop reads and writes: the sample buffer when multisampling, else the
// framebuffer and the depth buffer (nullptr: nothing is hidden, nothing kept).
struct OpaqueDepths {
    SampleBuffer* samples = nullptr;
    DepthBuffer* depth = nullptr;
    Framebuffer* frame = nullptr;
};

// The offset of the one sample of a frame drawn without multisampling: the pixel's centre.
inline constexpr std::array<SampleOffset, 1> kCentreOnly{SampleOffset{0, 0, 0.0, 0.0}};

// `alpha_of(varying)`: the surface's alpha where the Varying is that. With `list`, the triangle
// blends and its fragments go there (those of alpha 0 are dropped); without, it is masked at `cutoff`.
template <typename Shader, Interpolation kMode, typename AlphaOf>
void gather_triangle(FragmentList* list, OpaqueDepths opaque, int frame_width,
                     const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, const Shader& shader,
                     AlphaOf alpha_of, float cutoff, PixelRect rows, std::span<const SampleOffset> offsets,
                     LaneBatch<Shader>& lanes) {
    using Varying = typename Shader::Varying;
    (void)shader;
    const std::optional<TriangleSetup<Shader>> setup = triangle_weights<Shader>(corners);
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
    constexpr bool kLinear = kMode == Interpolation::screen_linear;
    const auto depth_at = [&](double a, double b) {
        if constexpr (kLinear) {
            return static_cast<float>(z0 + z1 * a + z2 * b);
        } else {
            return static_cast<float>(1.0 / ((1.0 - a - b) * inv0 + a * inv1 + b * inv2));
        }
    };
    const auto varying_at = [&](double a, double b) -> PixelVarying<Varying> {
        if constexpr (!kLinear) {
            const double q1 = a * inv1, q2 = b * inv2, sum = (1.0 - a - b) * inv0 + q1 + q2;
            return perspective_varying<Shader>(base, along1, along2, weights, q1, q2, sum, 1.0 / sum);
        } else {
            const Varying varying = base + along1 * static_cast<float>(a) + along2 * static_cast<float>(b);
            if constexpr (NeedsFootprint<Shader>) {
                return {varying,
                        along1 * static_cast<float>(w1.per_pixel_x()) + along2 * static_cast<float>(w2.per_pixel_x()),
                        along1 * static_cast<float>(w1.per_pixel_y()) + along2 * static_cast<float>(w2.per_pixel_y())};
            } else {
                return {varying};
            }
        }
    };
    const SampleCoverage coverage(points, offsets);
    const int count = static_cast<int>(std::min<std::size_t>(offsets.size(), kMaxSamples));
    const std::uint32_t all = coverage.all();
    std::array<double, kMaxSamples> at_a{}, at_b{};
    std::array<float, kMaxSamples> at_z{};
    const auto width = static_cast<std::size_t>(frame_width);
    coverage.rows(rows, [&](int y, int begin, int end, int inner_begin, int inner_end) {
        float* const depth_row = opaque.samples == nullptr && opaque.depth != nullptr ? opaque.depth->row(y) : nullptr;
        for (int x = begin; x < end; ++x) {
            const std::uint32_t covered = x >= inner_begin && x < inner_end ? all : coverage.at(x, y);
            if (covered == 0) continue;
            const double a = w1.at(x, y), b = w2.at(x, y);
            float* nearest = nullptr;
            if (opaque.samples != nullptr) {
                opaque.samples->touch(x, y);  // its samples read as the background until drawn on
                nearest = opaque.samples->depths(x, y);
            } else if (depth_row != nullptr) {
                nearest = depth_row + x;
            }
            if (count == 1 && list != nullptr) {  // one sample at the centre: its weights are the pixel's
                const float z = depth_at(a, b);
                if (nearest != nullptr && z > nearest[0]) continue;  // something opaque is nearer
                const PixelVarying<Varying> shaded = varying_at(a, b);
                const float alpha = alpha_of(shaded.value);
                if (!(alpha > 0.0F)) continue;  // shows nothing
                Fragment& fragment = list->add(
                    z, std::min(alpha, 1.0F),
                    static_cast<std::uint32_t>(static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)), 1);
                lanes.add(fragment.colour, 1, shaded);
                continue;
            }
            std::uint32_t passed = 0;
            for (int s = 0; s < count; ++s) {
                if ((covered & (std::uint32_t{1} << s)) == 0) continue;
                const auto k = static_cast<std::size_t>(s);
                const SampleOffset& o = offsets[k];
                at_a[k] = a + o.x * w1.per_pixel_x() + o.y * w1.per_pixel_y();
                at_b[k] = b + o.x * w2.per_pixel_x() + o.y * w2.per_pixel_y();
                at_z[k] = depth_at(at_a[k], at_b[k]);
                if (nearest != nullptr && at_z[k] > nearest[s]) continue;  // something opaque is nearer
                passed |= std::uint32_t{1} << s;
            }
            if (list == nullptr) {  // masked: each sample's own alpha against the cutoff
                for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
                    if ((passed & (std::uint32_t{1} << k)) != 0 &&
                        !(alpha_of(varying_at(at_a[k], at_b[k]).value) >= cutoff))
                        passed &= ~(std::uint32_t{1} << k);
                }
            }
            if (passed == 0) continue;
            // Shaded once, at the centre or at the centroid of the samples it reaches; sorted by their mean depth.
            double sum_a = 0.0, sum_b = 0.0, sum_z = 0.0;
            int inside = 0;
            for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
                if ((passed & (std::uint32_t{1} << k)) == 0) continue;
                sum_a += at_a[k], sum_b += at_b[k], sum_z += at_z[k], ++inside;
                if (list == nullptr && nearest != nullptr) nearest[k] = at_z[k];
            }
            const PixelVarying<Varying> shaded =
                passed == all ? varying_at(a, b) : varying_at(sum_a / inside, sum_b / inside);
            const std::size_t pixel =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(frame_width) + static_cast<std::size_t>(x);
            if (list == nullptr) {
                std::uint8_t* out =
                    opaque.samples != nullptr ? opaque.samples->colours(x, y) : opaque.frame->pixels() + pixel * 3;
                lanes.add(out, opaque.samples != nullptr ? passed : 1U, shaded);
                continue;
            }
            const float alpha = alpha_of(shaded.value);
            if (!(alpha > 0.0F)) continue;  // shows nothing
            Fragment& fragment = list->add(static_cast<float>(sum_z / inside), std::min(alpha, 1.0F),
                                           static_cast<std::uint32_t>(pixel), static_cast<std::uint16_t>(passed));
            lanes.add(fragment.colour, 1, shaded);
        }
    });
}

}  // namespace raster::detail
