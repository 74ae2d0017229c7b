#pragma once

#include "rasterize/edge_function.hpp"

#include <raster/rasterize/fill.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <span>

// Which samples of each pixel a triangle covers: exactly the pixels that rasterize_convex fills
// with the triangle moved by minus each sample's offset, found with one pass over the rows.
namespace raster::detail {

// A sample position in whole subpixels and in pixels: the offsets are multiples of 1/16 pixel.
struct SampleOffset {
    std::int32_t x_subpixels;
    std::int32_t y_subpixels;
    double x;
    double y;
};

// The most samples a pixel has.
inline constexpr int kMaxSamples = 16;

class SampleCoverage {
public:
    // For a triangle of non-zero area; at most kMaxSamples offsets are used.
    SampleCoverage(const std::array<SubpixelPoint, 3>& points, std::span<const SampleOffset> offsets) noexcept
        : count_(static_cast<int>(std::min<std::size_t>(offsets.size(), kMaxSamples))) {
        if (count_ == 0) return;                               // no samples: nothing covered (usable_ stays 0)
        const bool clockwise = twice_signed_area(points) < 0;  // walked the other way, as the fill does
        for (std::size_t k = 0; k < 3; ++k) {
            const SubpixelPoint a = points[k], b = points[(k + 1) % 3];
            edges_[k] = clockwise ? EdgeFunction::through(b, a) : EdgeFunction::through(a, b);
        }
        low_y_ = std::min({points[0].y, points[1].y, points[2].y});
        high_y_ = std::max({points[0].y, points[1].y, points[2].y});
        constexpr std::int64_t limit = std::int64_t{kMaxSubpixelCoordinate} * kSubpixelOne;
        for (int s = 0; s < count_; ++s) {
            const SampleOffset& o = offsets[static_cast<std::size_t>(s)];
            // A sample whose moved triangle leaves the coordinate limit covers nothing, as the fill draws nothing then.
            bool within = true;
            for (const SubpixelPoint p : points) {
                within = within && std::abs(std::int64_t{p.x} - o.x_subpixels) <= limit &&
                         std::abs(std::int64_t{p.y} - o.y_subpixels) <= limit;
            }
            if (within) usable_ |= std::uint32_t{1} << s;
            low_dy_ = std::min(low_dy_, o.y_subpixels), high_dy_ = std::max(high_dy_, o.y_subpixels);
            for (std::size_t k = 0; k < 3; ++k)
                shift_[k][static_cast<std::size_t>(s)] = edges_[k].shift(o.x_subpixels, o.y_subpixels);
        }
        for (std::size_t k = 0; k < 3; ++k) {
            const auto shifts = std::span(shift_[k]).first(static_cast<std::size_t>(count_));
            widest_[k] = *std::max_element(shifts.begin(), shifts.end());
            narrowest_[k] = *std::min_element(shifts.begin(), shifts.end());
        }
    }

    [[nodiscard]] std::uint32_t all() const noexcept { return (std::uint32_t{1} << count_) - 1; }

    // Calls visit(y, begin, end, inner_begin, inner_end) for every row of `clip` where some
    // sample may be covered: columns [begin, end) hold every covered pixel, and every sample of
    // the pixels in [inner_begin, inner_end) is covered (an empty range when none is).
    template <typename Visit>
    void rows(const PixelRect& clip, Visit visit) const {
        if (usable_ == 0) return;
        // Pixel rows whose centre may meet a moved triangle: its corners' rows moved by the offsets.
        const std::int64_t first_row =
            std::max<std::int64_t>(-((-(std::int64_t{low_y_} - high_dy_)) >> kSubpixelBits), clip.y);
        const std::int64_t last_row = std::min<std::int64_t>((std::int64_t{high_y_} - low_dy_) >> kSubpixelBits,
                                                             std::int64_t{clip.y} + clip.height - 1);
        const bool every_sample = usable_ == all();
        for (std::int64_t row = first_row; row <= last_row; ++row) {
            std::int64_t first = clip.x, last = std::int64_t{clip.x} + clip.width - 1;
            for (std::size_t k = 0; k < 3; ++k) clamp_to_edge(edges_[k], row, first, last, widest_[k]);
            if (first > last) continue;
            std::int64_t inner_first = first, inner_last = every_sample ? last : first - 1;
            for (std::size_t k = 0; k < 3; ++k) clamp_to_edge(edges_[k], row, inner_first, inner_last, narrowest_[k]);
            if (inner_first > inner_last) inner_first = inner_last = first - 1;
            visit(static_cast<int>(row), static_cast<int>(first), static_cast<int>(last + 1),
                  static_cast<int>(inner_first), static_cast<int>(inner_last + 1));
        }
    }

    // The samples of pixel (x, y) inside the triangle, bit s for sample s.
    [[nodiscard]] std::uint32_t at(int x, int y) const noexcept {
        std::array<std::int64_t, 3> e{};
        for (std::size_t k = 0; k < 3; ++k) e[k] = edges_[k].at(x, y) - edges_[k].bias;
        std::uint32_t covered = 0;
        for (std::size_t s = 0; s < static_cast<std::size_t>(count_); ++s) {
            const bool inside = e[0] + shift_[0][s] >= 0 && e[1] + shift_[1][s] >= 0 && e[2] + shift_[2][s] >= 0;
            covered |= static_cast<std::uint32_t>(inside) << s;
        }
        return covered & usable_;
    }

private:
    int count_;
    std::array<EdgeFunction, 3> edges_{};
    std::array<std::array<std::int64_t, kMaxSamples>, 3> shift_{};  // each edge's gain at each sample
    std::array<std::int64_t, 3> widest_{}, narrowest_{};            // its largest and smallest gain
    std::uint32_t usable_ = 0;
    std::int32_t low_y_ = 0, high_y_ = 0;
    std::int32_t low_dy_ = 0, high_dy_ = 0;
};

}  // namespace raster::detail
