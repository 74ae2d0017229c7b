#pragma once

#include "rasterize/strip_bins.hpp"

#include <algorithm>
#include <cmath>

// Splats or lines binned by the strips of rows they reach, as StripBins bins triangles: each
// strip draws its items in the order they were added, so the picture is the same whatever the
// number of threads.
namespace raster::detail {

template <typename Item>
class ItemBins {
public:
    explicit ItemBins(const StripLayout& layout) : height_(layout.height), rows_(layout.rows), lists_(layout.count()) {}

    void reserve(std::size_t items) { lists_.reserve(items); }

    // Keeps an item that reaches rows from `top` to `bottom` (continuous pixel rows), if any row
    // of the image lies between them.
    void add(const Item& item, double top, double bottom) {
        if (!(top <= bottom)) return;  // NaN, or nothing
        const double first_row = std::max(std::ceil(top), 0.0), last_row = std::min(std::floor(bottom), height_ - 1.0);
        if (first_row > last_row) return;
        lists_.keep(item, static_cast<int>(first_row) / rows_, static_cast<int>(last_row) / rows_);
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
    StripLists<Item> lists_;
};

}  // namespace raster::detail
