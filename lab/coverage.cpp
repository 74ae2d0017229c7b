#include "coverage.hpp"

#include <algorithm>
#include <numeric>

namespace lab {

Coverage::Coverage(PixelRect rect)
    : rect_(rect), counts_(static_cast<std::size_t>(rect.width) * static_cast<std::size_t>(rect.height)) {}

void Coverage::hit_row(std::int64_t y, std::int64_t x_begin, std::int64_t x_end) {
    if (y < rect_.y || y >= std::int64_t{rect_.y} + rect_.height) return;
    x_begin = std::max<std::int64_t>(x_begin, rect_.x);
    x_end = std::min<std::int64_t>(x_end, std::int64_t{rect_.x} + rect_.width);
    for (std::int64_t x = x_begin; x < x_end; ++x) ++counts_[index(x, y)];
}

std::int64_t Coverage::total() const { return std::accumulate(counts_.begin(), counts_.end(), std::int64_t{0}); }

void Coverage::clear() { std::fill(counts_.begin(), counts_.end(), 0); }

}  // namespace lab
