#pragma once

#include "rasterize/strip_bins.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

// Small items (splats) binned like ItemBins, but copied into strip order once a batch is
// complete: each strip then reads its items from one run of memory, in the order they were
// added, and the buffers keep their room when the batch is refilled, so a big cloud drawn in
// rounds allocates only in its first.
namespace raster::detail {

template <typename Item>
class StripSorted {
public:
    explicit StripSorted(const StripLayout& layout)
        : height_(layout.height), rows_(layout.rows), starts_(static_cast<std::size_t>(layout.count() + 1), 0) {}

    // Empties the batch, keeping its room, for `items` more.
    void refill(std::size_t items) {
        kept_.clear();
        kept_.reserve(items);
        sorted_.clear();
        std::fill(starts_.begin(), starts_.end(), 0U);
    }

    // Keeps an item that reaches rows from `top` to `bottom` (continuous pixel rows), if any row
    // of the image lies between them: ItemBins::add's rule.
    void add(const Item& item, double top, double bottom) {
        if (!(top <= bottom)) return;  // NaN, or nothing
        const double first_row = std::max(std::ceil(top), 0.0), last_row = std::min(std::floor(bottom), height_ - 1.0);
        if (first_row > last_row) return;
        const int first = static_cast<int>(first_row) / rows_, last = static_cast<int>(last_row) / rows_;
        kept_.push_back({item, first, last});
        for (int s = first; s <= last; ++s) ++starts_[static_cast<std::size_t>(s) + 1];
    }

    // Copies the kept items into strip order; call once, after the last add().
    void finish() {
        for (std::size_t s = 1; s < starts_.size(); ++s) starts_[s] += starts_[s - 1];
        sorted_.resize(starts_.back());
        filled_.assign(starts_.begin(), starts_.end() - 1);
        for (const Kept& kept : kept_) {
            for (int s = kept.first; s <= kept.last; ++s) sorted_[filled_[static_cast<std::size_t>(s)]++] = kept.item;
        }
    }

    // Strip s's items, in the order they were added.
    [[nodiscard]] std::span<const Item> in(int s) const noexcept {
        const auto strip = static_cast<std::size_t>(s);
        return std::span<const Item>(sorted_).subspan(starts_[strip], starts_[strip + 1] - starts_[strip]);
    }

private:
    struct Kept {
        Item item;
        int first;  // strips, not rows
        int last;
    };
    int height_;
    int rows_;
    std::vector<Kept> kept_;
    std::vector<Item> sorted_;
    std::vector<std::uint32_t> starts_;  // per strip, where its items begin; one past the end last
    std::vector<std::uint32_t> filled_;
};

}  // namespace raster::detail
