#pragma once

#include "rasterize/strip_bins.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

// Splats or lines binned by the strips of rows they reach, as StripBins bins triangles: each
// strip draws its items in the order they were added, so the picture is the same whatever the
// number of threads.
namespace raster::detail {

template <typename Item>
class ItemBins {
public:
    explicit ItemBins(const StripLayout& layout)
        : height_(layout.height), rows_(layout.rows), starts_(static_cast<std::size_t>(layout.count() + 1), 0) {}

    void reserve(std::size_t items) {
        items_.reserve(items);
        spans_.reserve(items);
    }

    // Keeps an item that reaches rows from `top` to `bottom` (continuous pixel rows), if any row
    // of the image lies between them.
    void add(const Item& item, double top, double bottom) {
        if (!(top <= bottom)) return;  // NaN, or nothing
        const double first_row = std::max(std::ceil(top), 0.0), last_row = std::min(std::floor(bottom), height_ - 1.0);
        if (first_row > last_row) return;
        const int first = static_cast<int>(first_row) / rows_, last = static_cast<int>(last_row) / rows_;
        items_.push_back(item);
        spans_.push_back({first, last});
        for (int s = first; s <= last; ++s) ++starts_[static_cast<std::size_t>(s) + 1];
    }

    // Lays out every strip's list; call once, after the last add().
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
    int height_;
    int rows_;
    std::vector<Item> items_;
    std::vector<RowRange> spans_;        // strips, not rows: first and last
    std::vector<std::uint32_t> starts_;  // per strip, where its members begin; one past the end last
    std::vector<std::uint32_t> members_;
};

}  // namespace raster::detail
