#include "io/webp/changed_region.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace raster::detail {

Region changed_region(const Framebuffer& before, const Framebuffer& after) {
    const int w = after.width(), h = after.height();
    const auto row_bytes = static_cast<std::size_t>(w) * 3;
    const std::uint8_t* a = before.bytes().data();
    const std::uint8_t* b = after.bytes().data();
    int top = h, bottom = -1, left = w, right = -1;
    const auto same = [](const std::uint8_t* p, const std::uint8_t* q) {
        return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    };
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* ra = a + static_cast<std::size_t>(y) * row_bytes;
        const std::uint8_t* rb = b + static_cast<std::size_t>(y) * row_bytes;
        if (std::equal(ra, ra + row_bytes, rb)) continue;
        top = std::min(top, y);
        bottom = y;
        // Only what would widen the rectangle is looked at: left of it, and right of it.
        int x0 = 0;
        while (x0 < left && same(ra + x0 * 3, rb + x0 * 3)) ++x0;
        left = std::min(left, x0);
        int x1 = w - 1;
        while (x1 > right && same(ra + x1 * 3, rb + x1 * 3)) --x1;
        right = std::max(right, x1);
    }
    if (bottom < 0) return {};
    const int x = left & ~1, y = top & ~1;
    return {x, y, right + 1 - x, bottom + 1 - y};
}

}  // namespace raster::detail
