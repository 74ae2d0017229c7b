#pragma once

#include <raster/image/subpixel.hpp>

#include <algorithm>
#include <cstdint>

// The exact edge test behind every fill: an integer function of the pixel that is >= a bias
// inside the edge, with the top-left rule in the bias (doc/conventions.md#fill).
namespace raster::detail {

// floor(n / d) for d > 0. Operands that fit 32 bits, the common case for small polygons, take
// the 32-bit divide, which is several times faster than the 64-bit one on x86-64.
inline std::int64_t floor_div(std::int64_t n, std::int64_t d) noexcept {
    if (n == static_cast<std::int32_t>(n) && d == static_cast<std::int32_t>(d)) {
        const auto n32 = static_cast<std::int32_t>(n);
        const auto d32 = static_cast<std::int32_t>(d);
        const std::int32_t q = n32 / d32;
        return (q * d32 != n32 && n32 < 0) ? q - 1 : q;
    }
    const std::int64_t q = n / d;
    return (q * d != n && n < 0) ? q - 1 : q;
}

// E(i, j) = step_x * i + step_y * j + offset at pixel (i, j), oriented so the inside is E >= bias;
// bias is 1 on edges that are neither top nor left, so samples exactly on them stay outside.
struct EdgeFunction {
    std::int64_t step_x;
    std::int64_t step_y;
    std::int64_t offset;
    std::int64_t bias;

    static EdgeFunction through(SubpixelPoint a, SubpixelPoint b) noexcept {
        const std::int64_t ex = std::int64_t{b.x} - a.x;
        const std::int64_t ey = std::int64_t{b.y} - a.y;
        // The inward normal is (-ey, ex): a left edge has it pointing right, a top edge down.
        const bool top_left = ey < 0 || (ey == 0 && ex > 0);
        return {-ey * kSubpixelOne, ex * kSubpixelOne, ey * a.x - ex * a.y, top_left ? 0 : 1};
    }
    [[nodiscard]] std::int64_t at(std::int64_t i, std::int64_t j) const noexcept {
        return step_x * i + step_y * j + offset;
    }
    // What E gains at a point (dx, dy) subpixels from the pixel centre: the same as the offset
    // gains when the polygon moves by (-dx, -dy), exactly (the steps are whole multiples of a pixel).
    [[nodiscard]] std::int64_t shift(std::int32_t dx, std::int32_t dy) const noexcept {
        return (step_x / kSubpixelOne) * dx + (step_y / kSubpixelOne) * dy;
    }
};

// Narrows [first, last] to the columns of `row` inside one edge moved by `shift`:
// step_x * i >= need. Solving with one exact division per edge and row measured faster than
// stepping quotient and remainder from row to row (doc/lab/README.md).
inline void clamp_to_edge(const EdgeFunction& edge, std::int64_t row, std::int64_t& first, std::int64_t& last,
                          std::int64_t shift = 0) noexcept {
    const std::int64_t need = edge.bias - (edge.step_y * row + edge.offset + shift);
    if (edge.step_x > 0) {
        first = std::max(first, -floor_div(-need, edge.step_x));
    } else if (edge.step_x < 0) {
        last = std::min(last, floor_div(-need, -edge.step_x));
    } else if (need > 0) {
        last = first - 1;  // a horizontal edge with the whole row outside it
    }
}

}  // namespace raster::detail
