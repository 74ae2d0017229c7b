#pragma once

#include "rasterize/triangle_loop.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

// A render in strips of rows: an object's triangles are gathered once, binned by the strips
// their pixel centres can reach, and each strip is cleared and drawn while its colour and depth
// rows sit in cache. Strips go to threads in any order and the result is bit-identical, since
// every pixel still meets the same triangles in the same order. An object's facets may be
// gathered in several batches, one StripBins each, drawn in batch order.
namespace raster::detail {

// Rows per strip: a power of two from 4 to 64 keeping a strip's colour and depth (7 bytes a
// pixel) near 256 KiB, well inside one core's cache.
inline int strip_rows(int width) noexcept {
    const long fits = (256L * 1024L) / (7L * std::max(width, 1));
    int rows = 4;
    while (rows < 64 && 2L * rows <= fits) rows *= 2;
    return rows;
}

// How a frame is cut into strips: strip_rows(width) rows each, the last strip what is left.
struct StripLayout {
    int width;
    int height;
    int rows;
    [[nodiscard]] static StripLayout of(int width, int height) noexcept { return {width, height, strip_rows(width)}; }
    [[nodiscard]] int count() const noexcept { return (height + rows - 1) / rows; }
    [[nodiscard]] PixelRect strip(int s) const noexcept {
        return {0, s * rows, width, std::min(rows, height - s * rows)};
    }
};

inline std::int32_t floor_div(std::int32_t a, std::int32_t b) noexcept {
    return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

// The rows whose pixel centres lie between a triangle's lowest and highest corner (widened by
// `reach` subpixels each way, for samples away from the centres), clamped to 0..height-1;
// first > last when there are none.
struct RowRange {
    int first;
    int last;
};
inline RowRange rows_reached(const std::array<SubpixelPoint, 3>& points, int height, std::int32_t reach = 0) noexcept {
    const std::int32_t low = std::min({points[0].y, points[1].y, points[2].y}) - reach;
    const std::int32_t high = std::max({points[0].y, points[1].y, points[2].y}) + reach;
    return {std::max(-floor_div(-low, kSubpixelOne), 0), std::min(floor_div(high, kSubpixelOne), height - 1)};
}

// Whether no column's pixel centre lies between a triangle's leftmost and rightmost corner: a
// sliver the fill would find empty, dropped before any setup (rows_reached does the same for rows).
inline bool between_columns(const std::array<SubpixelPoint, 3>& points, std::int32_t reach = 0) noexcept {
    const std::int32_t low = std::min({points[0].x, points[1].x, points[2].x}) - reach;
    const std::int32_t high = std::max({points[0].x, points[1].x, points[2].x}) + reach;
    return -floor_div(-low, kSubpixelOne) > floor_div(high, kSubpixelOne);
}

// Items kept with the strips they reach, and each strip's items in the order they were kept: a
// counting sort, so that strips drawn on any threads meet their items in one order.
template <typename Item>
class StripLists {
public:
    explicit StripLists(int strips) : starts_(static_cast<std::size_t>(strips + 1), 0) {}

    void reserve(std::size_t items) {
        items_.reserve(items);
        spans_.reserve(items);
    }

    // Keeps an item that reaches strips `first` to `last`.
    void keep(const Item& item, int first, int last) {
        items_.push_back(item);
        spans_.push_back({first, last});
        for (int s = first; s <= last; ++s) ++starts_[static_cast<std::size_t>(s) + 1];
    }

    // Lays out every strip's list; call once, after the last keep().
    void finish() {
        for (std::size_t s = 1; s < starts_.size(); ++s) starts_[s] += starts_[s - 1];
        members_.resize(starts_.back());
        std::vector<std::uint32_t> filled(starts_.begin(), starts_.end() - 1);
        for (std::size_t t = 0; t < spans_.size(); ++t) {
            for (int s = spans_[t].first; s <= spans_[t].last; ++s)
                members_[filled[static_cast<std::size_t>(s)]++] = static_cast<std::uint32_t>(t);
        }
    }

    template <typename Draw>
    void for_each_in(int s, Draw draw) const {
        for (std::uint32_t k = starts_[static_cast<std::size_t>(s)]; k < starts_[static_cast<std::size_t>(s) + 1]; ++k)
            draw(items_[members_[k]]);
    }

private:
    std::vector<Item> items_;
    std::vector<RowRange> spans_;        // strips, not rows: first and last
    std::vector<std::uint32_t> starts_;  // per strip, where its members begin; one past the end last
    std::vector<std::uint32_t> members_;
};

// One object's triangles with their corners shaded, and for every strip the triangles in it,
// in the order they were added.
template <typename Varying>
class StripBins {
public:
    using Triangle = std::array<ShadedCorner<Varying>, 3>;

    // `reach`: how far, in subpixels, a sample may lie from its pixel centre (0 without multisampling).
    explicit StripBins(const StripLayout& layout, std::int32_t reach = 0)
        : height_(layout.height), rows_(layout.rows), reach_(reach), lists_(layout.count()) {}

    // Room for this many triangles: a facet is one unless clipping splits it.
    void reserve(std::size_t triangles) { lists_.reserve(triangles); }

    // Keeps a triangle that can cover a pixel centre of the image; counts it into its strips.
    void add(const Triangle& corners) {
        const std::array<SubpixelPoint, 3> points{corners[0].at, corners[1].at, corners[2].at};
        const RowRange rows = rows_reached(points, height_, reach_);
        if (rows.first > rows.last || between_columns(points, reach_)) return;  // covers no sample of the image
        lists_.keep(corners, rows.first / rows_, rows.last / rows_);
    }

    // Lays out every strip's list; call once, after the last add().
    void finish() { lists_.finish(); }

    template <typename Draw>
    void for_each_in(int s, Draw draw) const {
        lists_.for_each_in(s, draw);
    }

private:
    int height_;
    int rows_;
    std::int32_t reach_;
    StripLists<Triangle> lists_;
};

}  // namespace raster::detail
