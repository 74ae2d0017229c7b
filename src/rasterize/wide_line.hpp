#pragma once

#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/depth_buffer.hpp>

#include "rasterize/lane_batch.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/sample_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

// A line segment drawn as a capsule of a width in pixels: the samples within half the width of
// the segment are covered, so its edges are anti-aliased by the samples; depth and colour run
// along it (doc/conventions.md#points-and-lines).
namespace raster::detail {

// A segment on screen: its ends in continuous pixel coordinates, their view depths (already
// moved toward the viewer by the depth rule) and colours. `perspective`: depth runs through
// 1 / w along the screen, as a surface's does; else linearly.
struct WideLine {
    double ax, ay, bx, by;
    float depth_a, depth_b;
    LinearRgb colour_a, colour_b;
    bool perspective = false;
};

// What a capsule gives one sample: whether it is covered and, if so, where along the segment.
class Capsule {
public:
    Capsule(const WideLine& line, double half_width) noexcept
        : line_(line), dx_(line.bx - line.ax), dy_(line.by - line.ay), h2_(half_width * half_width),
          length2_(dx_ * dx_ + dy_ * dy_), half_(half_width) {}

    // Where along the segment (0 at a, 1 at b) the point nearest (x, y) lies, or -1 when (x, y)
    // is farther than half the width from the segment.
    [[nodiscard]] double along(double x, double y) const noexcept {
        const double px = x - line_.ax, py = y - line_.ay;
        const double t = length2_ > 0.0 ? std::clamp((px * dx_ + py * dy_) / length2_, 0.0, 1.0) : 0.0;
        const double ex = px - t * dx_, ey = py - t * dy_;
        return ex * ex + ey * ey <= h2_ ? t : -1.0;
    }

    [[nodiscard]] float depth(double t) const noexcept {
        if (line_.perspective) return static_cast<float>(1.0 / ((1.0 - t) / line_.depth_a + t / line_.depth_b));
        return static_cast<float>(line_.depth_a + t * (static_cast<double>(line_.depth_b) - line_.depth_a));
    }
    [[nodiscard]] Rgb colour(double t) const noexcept {
        return srgb_from_linear(line_.colour_a + (line_.colour_b - line_.colour_a) * static_cast<float>(t));
    }

    // The columns of row y where the capsule, widened by `reach` pixels, may cover a sample:
    // the band along the infinite line cut by the capsule's box; first > last when none.
    void columns(double y, double reach, int width, int& first, int& last) const noexcept {
        const double grow = half_ + reach;
        double low = std::min(line_.ax, line_.bx) - grow, high = std::max(line_.ax, line_.bx) + grow;
        if (std::abs(dy_) > 1e-9 * std::sqrt(length2_)) {
            // |(p - a) x d| <= grow |d| on this row, solved for x.
            const double centre = line_.ax + (y - line_.ay) * dx_ / dy_;
            const double spread = grow * std::sqrt(length2_) / std::abs(dy_);
            low = std::max(low, centre - spread), high = std::min(high, centre + spread);
        }
        first = static_cast<int>(std::clamp(std::ceil(low), 0.0, static_cast<double>(width)));
        last = static_cast<int>(std::clamp(std::floor(high), -1.0, static_cast<double>(width - 1)));
    }

    // The rows the capsule, widened by `reach`, may reach.
    [[nodiscard]] double top(double reach) const noexcept { return std::min(line_.ay, line_.by) - half_ - reach; }
    [[nodiscard]] double bottom(double reach) const noexcept { return std::max(line_.ay, line_.by) + half_ + reach; }

private:
    WideLine line_;
    double dx_, dy_, h2_, length2_, half_;
};

// The rows [first, last] of `rows` from `top` to `bottom`.
inline void rows_between(double top, double bottom, const PixelRect& rows, int& first, int& last) noexcept {
    const double end = rows.y + rows.height;  // one past the last row
    first = static_cast<int>(std::clamp(std::ceil(top), static_cast<double>(rows.y), end));
    last = static_cast<int>(std::clamp(std::floor(bottom), rows.y - 1.0, end - 1.0));
}

// Draws a line `width` pixels wide into rows `rows` at one sample per pixel (its centre).
inline void draw_wide_line(Framebuffer& colour, DepthBuffer* depth, const WideLine& line, float width,
                           const PixelRect& rows) noexcept {
    const Capsule capsule(line, width / 2.0);
    int y_first = 0, y_last = -1;
    rows_between(capsule.top(0.0), capsule.bottom(0.0), rows, y_first, y_last);
    for (int y = y_first; y <= y_last; ++y) {
        int x_first = 0, x_last = -1;
        capsule.columns(y, 0.0, colour.width(), x_first, x_last);
        float* nearest = depth != nullptr && x_first <= x_last ? depth->row(y) : nullptr;
        for (int x = x_first; x <= x_last; ++x) {
            const double t = capsule.along(x, y);
            if (t < 0.0) continue;
            if (nearest != nullptr) {
                const float z = capsule.depth(t);
                if (z > nearest[x]) continue;  // something nearer is already there
                nearest[x] = z;
            }
            const Rgb c = capsule.colour(t);
            std::uint8_t* out =
                colour.pixels() +
                (static_cast<std::size_t>(y) * static_cast<std::size_t>(colour.width()) + static_cast<std::size_t>(x)) *
                    3;
            out[0] = c.r, out[1] = c.g, out[2] = c.b;
        }
    }
}

// The same at the samples of `target`, each tested (when `depth_test`) at its own depth along the
// line; the pixel takes one colour, at the covered samples' mean place along the line.
inline void draw_wide_line_samples(SampleBuffer& target, bool depth_test, const WideLine& line, float width,
                                   const PixelRect& rows, std::span<const SampleOffset> offsets) noexcept {
    const Capsule capsule(line, width / 2.0);
    const std::size_t count = std::min<std::size_t>(offsets.size(), kMaxSamples);
    int y_first = 0, y_last = -1;
    rows_between(capsule.top(0.5), capsule.bottom(0.5), rows, y_first, y_last);
    for (int y = y_first; y <= y_last; ++y) {
        int x_first = 0, x_last = -1;
        capsule.columns(y, 0.5, target.width(), x_first, x_last);
        for (int x = x_first; x <= x_last; ++x) {
            std::uint32_t passed = 0;
            double sum = 0.0;
            int inside = 0;
            float* nearest = nullptr;
            for (std::size_t s = 0; s < count; ++s) {
                const double t = capsule.along(x + offsets[s].x, y + offsets[s].y);
                if (t < 0.0) continue;
                if (nearest == nullptr) target.touch(x, y), nearest = target.depths(x, y);
                const float z = capsule.depth(t);
                if (depth_test && z > nearest[s]) continue;  // something nearer is already there
                nearest[s] = z;
                passed |= std::uint32_t{1} << s;
                sum += t, ++inside;
            }
            if (passed != 0) write_samples(target.colours(x, y), passed, capsule.colour(sum / inside));
        }
    }
}

}  // namespace raster::detail
