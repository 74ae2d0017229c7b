#include <raster/rasterize/fill.hpp>

#include "rasterize/edge_function.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace raster {
namespace {

// The first and last pixel whose centre lies in [low, high] (subpixel units); an arithmetic
// shift is a floor division by kSubpixelOne.
std::int64_t first_pixel_at_or_after(std::int64_t low) { return -((-low) >> kSubpixelBits); }
std::int64_t last_pixel_at_or_before(std::int64_t high) { return high >> kSubpixelBits; }

using detail::EdgeFunction;

constexpr std::size_t kMaxCorners = 8;

}  // namespace

std::int64_t twice_signed_area(std::span<const SubpixelPoint> corners) noexcept {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const SubpixelPoint a = corners[i];
        const SubpixelPoint b = corners[i + 1 == corners.size() ? 0 : i + 1];  // no division in the loop
        sum += std::int64_t{a.x} * b.y - std::int64_t{b.x} * a.y;
    }
    return sum;
}

std::int64_t rasterize_convex(std::span<const SubpixelPoint> corners, PixelRect clip, SpanVisitor visit) {
    const std::size_t count = corners.size();
    if (count < 3 || count > kMaxCorners) return 0;
    constexpr std::int64_t limit = std::int64_t{kMaxSubpixelCoordinate} * kSubpixelOne;
    std::int64_t min_x = corners[0].x, max_x = corners[0].x, min_y = corners[0].y, max_y = corners[0].y;
    for (const SubpixelPoint c : corners) {
        if (std::abs(std::int64_t{c.x}) > limit || std::abs(std::int64_t{c.y}) > limit) return 0;
        min_x = std::min<std::int64_t>(min_x, c.x), max_x = std::max<std::int64_t>(max_x, c.x);
        min_y = std::min<std::int64_t>(min_y, c.y), max_y = std::max<std::int64_t>(max_y, c.y);
    }
    // Cheap rejections first: no pixel centre of the clip inside the bounding box.
    const std::int64_t first_row = std::max<std::int64_t>(first_pixel_at_or_after(min_y), clip.y);
    const std::int64_t last_row =
        std::min<std::int64_t>(last_pixel_at_or_before(max_y), std::int64_t{clip.y} + clip.height - 1);
    if (first_row > last_row || first_pixel_at_or_after(min_x) >= std::int64_t{clip.x} + clip.width ||
        last_pixel_at_or_before(max_x) < clip.x) {
        return 0;
    }
    const std::int64_t area = twice_signed_area(corners);
    if (area == 0) return 0;

    std::array<EdgeFunction, kMaxCorners> edges{};
    std::size_t edge_count = 0;
    for (std::size_t i = 0; i < count; ++i) {
        SubpixelPoint a = corners[i];
        SubpixelPoint b = corners[i + 1 == count ? 0 : i + 1];
        if (a == b) continue;           // a repeated corner bounds nothing: the polygon is the one without it
        if (area < 0) std::swap(a, b);  // walk every polygon in the same rotational sense
        edges[edge_count++] = EdgeFunction::through(a, b);
    }
    for (std::int64_t row = first_row; row <= last_row; ++row) {
        std::int64_t first = clip.x;
        std::int64_t last = std::int64_t{clip.x} + clip.width - 1;
        for (std::size_t i = 0; i < edge_count; ++i) detail::clamp_to_edge(edges[i], row, first, last);
        if (first <= last) visit({static_cast<int>(row), static_cast<int>(first), static_cast<int>(last + 1)});
    }
    return last_row - first_row + 1;
}

std::int64_t fill_convex(Framebuffer& framebuffer, std::span<const SubpixelPoint> corners, Rgb colour,
                         glm::ivec2 origin) {
    const PixelRect clip{origin.x, origin.y, framebuffer.width(), framebuffer.height()};
    return rasterize_convex(corners, clip, [&](Span span) {
        framebuffer.fill_row(span.y - origin.y, span.x_begin - origin.x, span.x_end - origin.x, colour);
    });
}

}  // namespace raster
