#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/depth_buffer.hpp>

#include "rasterize/sample_buffer.hpp"
#include "rasterize/sample_coverage.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>

// A point drawn as a round splat facing the viewer: a disc of one colour and one depth, covering
// the samples whose positions lie inside it (doc/conventions.md#points-and-lines).
namespace raster::detail {

// A splat's centre in continuous pixel coordinates (pixel centres on whole numbers), its view
// depth (already moved toward the viewer by the depth rule) and its colour.
struct Splat {
    float x;
    float y;
    float depth;
    Rgb colour;
};

// Whether the point (dx, dy) from a splat's centre lies on its disc of squared radius r2.
inline bool on_disc(double dx, double dy, double r2) noexcept { return dx * dx + dy * dy <= r2; }

// The pixel whose area holds the centre: it is always drawn, so no point vanishes between samples.
inline int pixel_holding(float centre) noexcept { return static_cast<int>(std::floor(centre + 0.5F)); }

// Draws a splat of `radius` pixels into rows `rows` of `colour` at one sample per pixel (the
// pixel centre), tested against `depth` when given.
inline void draw_splat(Framebuffer& colour, DepthBuffer* depth, const Splat& splat, float radius,
                       const PixelRect& rows) noexcept {
    const double r2 = static_cast<double>(radius) * radius;
    const int y_first = std::max(static_cast<int>(std::ceil(splat.y - radius)), rows.y);
    const int y_last = std::min(static_cast<int>(std::floor(splat.y + radius)), rows.y + rows.height - 1);
    const int own_x = pixel_holding(splat.x), own_y = pixel_holding(splat.y);
    const int width = colour.width();
    const auto draw_pixel = [&](int x, int y, float* nearest) {
        if (nearest != nullptr) {
            if (splat.depth > nearest[x]) return;  // something nearer is already there
            nearest[x] = splat.depth;
        }
        std::uint8_t* out =
            colour.pixels() +
            (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
        out[0] = splat.colour.r, out[1] = splat.colour.g, out[2] = splat.colour.b;
    };
    bool own_drawn = false;
    for (int y = y_first; y <= y_last; ++y) {
        const double dy = y - static_cast<double>(splat.y);
        const double half = std::sqrt(std::max(r2 - dy * dy, 0.0));
        const int x_first = std::max(static_cast<int>(std::ceil(splat.x - half)), 0);
        const int x_last = std::min(static_cast<int>(std::floor(splat.x + half)), width - 1);
        float* nearest = depth != nullptr && x_first <= x_last ? depth->row(y) : nullptr;
        for (int x = x_first; x <= x_last; ++x) {
            if (!on_disc(x - static_cast<double>(splat.x), dy, r2)) continue;
            own_drawn = own_drawn || (x == own_x && y == own_y);
            draw_pixel(x, y, nearest);
        }
    }
    if (!own_drawn && own_y >= rows.y && own_y < rows.y + rows.height && own_x >= 0 && own_x < width)
        draw_pixel(own_x, own_y, depth != nullptr ? depth->row(own_y) : nullptr);
}

// The farthest any sample lies from its pixel's centre along x or y: pixels farther than that
// beyond a disc hold none of its samples. A hair more, so rounding never drops one that would pass.
inline double sample_spread(std::span<const SampleOffset> offsets) noexcept {
    double spread = 0.0;
    for (const SampleOffset& offset : offsets) spread = std::max({spread, std::abs(offset.x), std::abs(offset.y)});
    return spread + 1e-6;
}

// Calls `draw` with the sample count as a constant where it is one of the standard counts (so
// the splat's loops over samples unroll), else with 0: any count.
template <typename Draw>
void with_sample_count(std::size_t count, const Draw& draw) {
    switch (count) {
    case 1: return draw(std::integral_constant<std::size_t, 1>{});
    case 2: return draw(std::integral_constant<std::size_t, 2>{});
    case 4: return draw(std::integral_constant<std::size_t, 4>{});
    case 8: return draw(std::integral_constant<std::size_t, 8>{});
    case 16: return draw(std::integral_constant<std::size_t, 16>{});
    default: return draw(std::integral_constant<std::size_t, 0>{});
    }
}

// The same at the samples of `target`: every sample inside the disc is tested (when
// `depth_test`) and written, so the disc's edge is anti-aliased by the samples. The pixel holding
// the centre always keeps at least its sample nearest the centre. `spread` is
// sample_spread(offsets); `Count`, when not 0, is the number of offsets, fixed so loops unroll.
template <std::size_t Count = 0>
inline void draw_splat_samples(SampleBuffer& target, bool depth_test, const Splat& splat, float radius, double spread,
                               const PixelRect& rows, std::span<const SampleOffset> offsets) noexcept {
    static_assert(Count <= kMaxSamples);
    const double r2 = static_cast<double>(radius) * radius;
    const std::size_t count = Count != 0 ? Count : std::min<std::size_t>(offsets.size(), kMaxSamples);
    const double reach = radius + spread;
    const int y_first = std::max(static_cast<int>(std::ceil(splat.y - reach)), rows.y);
    const int y_last = std::min(static_cast<int>(std::floor(splat.y + reach)), rows.y + rows.height - 1);
    const int x_first = std::max(static_cast<int>(std::ceil(splat.x - reach)), 0);
    const int x_last = std::min(static_cast<int>(std::floor(splat.x + reach)), target.width() - 1);
    const int own_x = pixel_holding(splat.x), own_y = pixel_holding(splat.y);
    // Selects, not branches: whether a cloud's splat lies in front is a coin toss the processor cannot predict.
    const auto draw_pixel = [&](int x, int y, std::uint32_t covered) {
        target.touch(x, y);
        float* nearest = target.depths(x, y);
        std::uint8_t* colours = target.colours(x, y);
        const std::uint32_t depth_bits = std::bit_cast<std::uint32_t>(splat.depth);
        const std::array<std::uint8_t, 3> colour{splat.colour.r, splat.colour.g, splat.colour.b};
        for (std::size_t s = 0; s < count; ++s) {
            const bool behind = depth_test && splat.depth > nearest[s];  // something nearer is already there
            const std::uint32_t keep = 0U - (((covered >> s) & 1U) & static_cast<std::uint32_t>(!behind));
            nearest[s] = std::bit_cast<float>((depth_bits & keep) | (std::bit_cast<std::uint32_t>(nearest[s]) & ~keep));
            const auto byte_keep = static_cast<std::uint8_t>(keep);
            for (std::size_t c = 0; c < 3; ++c) {
                std::uint8_t& out = colours[s * 3 + c];
                out = static_cast<std::uint8_t>((colour[c] & byte_keep) | (out & ~byte_keep));
            }
        }
    };
    // The sample of the own pixel nearest the centre, for a disc that covers none of them.
    const auto nearest_sample = [&](double dx, double dy) {
        std::size_t nearest = 0;
        double nearest_distance = 1e300;
        for (std::size_t s = 0; s < count; ++s) {
            const double sx = dx + offsets[s].x, sy = dy + offsets[s].y;
            if (sx * sx + sy * sy < nearest_distance) nearest_distance = sx * sx + sy * sy, nearest = s;
        }
        return std::uint32_t{1} << nearest;
    };
    std::array<double, Count != 0 ? Count : kMaxSamples> across{};  // each sample's squared distance along y
    for (int y = y_first; y <= y_last; ++y) {
        const double dy = y - static_cast<double>(splat.y);
        for (std::size_t s = 0; s < count; ++s) across[s] = (dy + offsets[s].y) * (dy + offsets[s].y);
        for (int x = x_first; x <= x_last; ++x) {
            const double dx = x - static_cast<double>(splat.x);
            std::uint32_t covered = 0;
            for (std::size_t s = 0; s < count; ++s) {
                // on_disc, its y term taken from the row.
                const double along = dx + offsets[s].x;
                if (along * along + across[s] <= r2) covered |= std::uint32_t{1} << s;
            }
            if (covered == 0 && x == own_x && y == own_y) covered = nearest_sample(dx, dy);
            if (covered != 0) draw_pixel(x, y, covered);
        }
    }
}

}  // namespace raster::detail
