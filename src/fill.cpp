#include <raster/fill.hpp>

#include <algorithm>
#include <cstdlib>
#include <array>
#include <limits>

namespace raster {
namespace {

// floor(n / d) and ceil(n / d) for d > 0.
std::int64_t floor_div(std::int64_t n, std::int64_t d) {
    const std::int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}
std::int64_t ceil_div(std::int64_t n, std::int64_t d) { return -floor_div(-n, d); }

// E(i, j) = step_x * i + step_y * j + offset at pixel (i, j), oriented so the inside is E >= bias;
// bias is 1 on edges that are neither top nor left, so samples exactly on them stay outside.
struct EdgeFunction {
    std::int64_t step_x;
    std::int64_t step_y;
    std::int64_t offset;
    std::int64_t bias;

    static EdgeFunction through(SubpixelPoint a, SubpixelPoint b) {
        const std::int64_t ex = std::int64_t{b.x} - a.x;
        const std::int64_t ey = std::int64_t{b.y} - a.y;
        // The inward normal is (-ey, ex): a left edge has it pointing right, a top edge down.
        const bool top_left = ey < 0 || (ey == 0 && ex > 0);
        return {-ey * kSubpixelOne, ex * kSubpixelOne, ey * a.x - ex * a.y, top_left ? 0 : 1};
    }
};

// The columns [first, last] of row j inside one edge; first > last when none are.
void clamp_to_edge(const EdgeFunction& edge, std::int64_t row, std::int64_t& first,
                   std::int64_t& last) {
    const std::int64_t need = edge.bias - (edge.step_y * row + edge.offset);  // step_x * i >= need
    if (edge.step_x > 0) {
        first = std::max(first, ceil_div(need, edge.step_x));
    } else if (edge.step_x < 0) {
        last = std::min(last, floor_div(-need, -edge.step_x));
    } else if (need > 0) {
        last = first - 1;
    }
}

constexpr std::size_t kMaxCorners = 8;

}  // namespace

std::int64_t twice_signed_area(std::span<const SubpixelPoint> corners) noexcept {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const SubpixelPoint a = corners[i];
        const SubpixelPoint b = corners[(i + 1) % corners.size()];
        sum += std::int64_t{a.x} * b.y - std::int64_t{b.x} * a.y;
    }
    return sum;
}

std::int64_t rasterize_convex(std::span<const SubpixelPoint> corners, PixelRect clip,
                              const std::function<void(Span)>& visit) {
    if (corners.size() < 3 || corners.size() > kMaxCorners) return 0;
    constexpr std::int64_t limit = std::int64_t{kMaxSubpixelCoordinate} * kSubpixelOne;
    for (const SubpixelPoint c : corners) {
        if (std::abs(std::int64_t{c.x}) > limit || std::abs(std::int64_t{c.y}) > limit) return 0;
    }
    const std::int64_t area = twice_signed_area(corners);
    if (area == 0) return 0;

    std::array<EdgeFunction, kMaxCorners> edges{};
    std::int64_t min_x = corners[0].x;
    std::int64_t max_x = corners[0].x;
    std::int64_t min_y = corners[0].y;
    std::int64_t max_y = corners[0].y;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        SubpixelPoint a = corners[i];
        SubpixelPoint b = corners[(i + 1) % corners.size()];
        if (area < 0) std::swap(a, b);  // walk every polygon in the same rotational sense
        edges[i] = EdgeFunction::through(a, b);
        min_x = std::min<std::int64_t>(min_x, corners[i].x);
        max_x = std::max<std::int64_t>(max_x, corners[i].x);
        min_y = std::min<std::int64_t>(min_y, corners[i].y);
        max_y = std::max<std::int64_t>(max_y, corners[i].y);
    }
    if (ceil_div(min_x, kSubpixelOne) >= std::int64_t{clip.x} + clip.width ||
        floor_div(max_x, kSubpixelOne) < clip.x) {
        return 0;  // entirely left or right of the clip
    }

    const std::int64_t first_row = std::max<std::int64_t>(ceil_div(min_y, kSubpixelOne), clip.y);
    const std::int64_t last_row =
        std::min<std::int64_t>(floor_div(max_y, kSubpixelOne), std::int64_t{clip.y} + clip.height - 1);
    for (std::int64_t row = first_row; row <= last_row; ++row) {
        std::int64_t first = clip.x;
        std::int64_t last = std::int64_t{clip.x} + clip.width - 1;
        for (std::size_t i = 0; i < corners.size() && first <= last; ++i) {
            clamp_to_edge(edges[i], row, first, last);
        }
        if (first <= last) {
            visit({static_cast<int>(row), static_cast<int>(first), static_cast<int>(last + 1)});
        }
    }
    return std::max<std::int64_t>(0, last_row - first_row + 1);
}

std::int64_t fill_convex(Framebuffer& framebuffer, std::span<const SubpixelPoint> corners,
                         Rgb colour, glm::ivec2 origin) {
    const PixelRect clip{origin.x, origin.y, framebuffer.width(), framebuffer.height()};
    return rasterize_convex(corners, clip, [&](Span span) {
        framebuffer.fill_row(span.y - origin.y, span.x_begin - origin.x, span.x_end - origin.x, colour);
    });
}

}  // namespace raster
