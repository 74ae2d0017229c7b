#include "fill_methods.hpp"

#include <raster/fill.hpp>
#include <raster/subpixel.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace lab {
namespace {

constexpr std::size_t kMaxCorners = 8;

struct Box {
    std::int64_t x0, y0, x1, y1;  // inclusive pixel bounds, clipped to the target
};

std::optional<Box> clipped_box(double min_x, double min_y, double max_x, double max_y,
                               const Coverage& target) {
    const PixelRect& r = target.rect();
    const Box box{std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(min_x)), r.x),
                  std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(min_y)), r.y),
                  std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(max_x)), std::int64_t{r.x} + r.width - 1),
                  std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(max_y)), std::int64_t{r.y} + r.height - 1)};
    if (box.x0 > box.x1 || box.y0 > box.y1) return std::nullopt;
    return box;
}

bool finite(std::span<const glm::dvec2> corners) {
    return std::all_of(corners.begin(), corners.end(),
                       [](glm::dvec2 c) { return std::isfinite(c.x) && std::isfinite(c.y); });
}

// The seed (0.0.6): corners rounded to whole pixels, float cross products, every sign agreeing.
void seed_bbox_float(std::span<const glm::dvec2> corners, Coverage& target) {
    if (!finite(corners) || corners.size() > kMaxCorners) return;
    std::array<glm::vec2, kMaxCorners> v{};
    float min_x = std::numeric_limits<float>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        v[i] = {static_cast<float>(std::floor(corners[i].x + 0.5)), static_cast<float>(std::floor(corners[i].y + 0.5))};
        min_x = std::min(min_x, v[i].x), max_x = std::max(max_x, v[i].x);
        min_y = std::min(min_y, v[i].y), max_y = std::max(max_y, v[i].y);
    }
    const auto box = clipped_box(min_x, min_y, max_x, max_y, target);
    if (!box) return;
    for (std::int64_t y = box->y0; y <= box->y1; ++y) {
        for (std::int64_t x = box->x0; x <= box->x1; ++x) {
            const glm::vec2 p{static_cast<float>(x), static_cast<float>(y)};
            int winding = 0;
            bool inside = true;
            for (std::size_t i = 0; i < corners.size() && inside; ++i) {
                const glm::vec2 e = v[(i + 1) % corners.size()] - v[i];
                const glm::vec2 w = p - v[i];
                const float cross = e.x * w.y - e.y * w.x;
                if (cross == 0.0F) continue;
                const int sign = cross > 0.0F ? 1 : -1;
                if (winding == 0) winding = sign;
                inside = winding == sign;
            }
            if (inside) target.hit(x, y);
        }
    }
}

// Integer edge functions on corners snapped to 1/2^Bits pixel, top-left rule, one pixel at a
// time with incremental steps across each row.
template <int Bits>
void edge_fixed(std::span<const glm::dvec2> corners, Coverage& target) {
    constexpr std::int64_t one = std::int64_t{1} << Bits;
    constexpr double limit = double{raster::kMaxSubpixelCoordinate} * one;
    const std::size_t n = corners.size();
    if (n < 3 || n > kMaxCorners) return;
    std::array<std::int64_t, kMaxCorners> xs{}, ys{};
    for (std::size_t i = 0; i < n; ++i) {
        const double x = std::floor(corners[i].x * one + 0.5), y = std::floor(corners[i].y * one + 0.5);
        if (!(std::abs(x) <= limit && std::abs(y) <= limit)) return;
        xs[i] = static_cast<std::int64_t>(x), ys[i] = static_cast<std::int64_t>(y);
    }
    std::int64_t area = 0;
    for (std::size_t i = 0; i < n; ++i) area += xs[i] * ys[(i + 1) % n] - xs[(i + 1) % n] * ys[i];
    if (area == 0) return;

    std::array<std::int64_t, kMaxCorners> step_x{}, step_y{}, offset{};
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t a = i, b = (i + 1) % n;
        if (area < 0) std::swap(a, b);
        const std::int64_t ex = xs[b] - xs[a], ey = ys[b] - ys[a];
        const bool top_left = ey < 0 || (ey == 0 && ex > 0);
        step_x[i] = -ey * one;
        step_y[i] = ex * one;
        offset[i] = ey * xs[a] - ex * ys[a] - (top_left ? 0 : 1);  // inside: value >= 0
    }
    const auto [min_x, max_x] = std::minmax_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(n));
    const auto [min_y, max_y] = std::minmax_element(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(n));
    const auto box = clipped_box(static_cast<double>(*min_x) / one, static_cast<double>(*min_y) / one,
                                 static_cast<double>(*max_x) / one, static_cast<double>(*max_y) / one, target);
    if (!box) return;
    std::array<std::int64_t, kMaxCorners> row{};
    for (std::size_t i = 0; i < n; ++i) row[i] = step_x[i] * box->x0 + step_y[i] * box->y0 + offset[i];
    for (std::int64_t y = box->y0; y <= box->y1; ++y) {
        std::array<std::int64_t, kMaxCorners> value = row;
        for (std::int64_t x = box->x0; x <= box->x1; ++x) {
            bool inside = true;
            for (std::size_t i = 0; i < n; ++i) {
                inside &= value[i] >= 0;
                value[i] += step_x[i];
            }
            if (inside) target.hit(x, y);
        }
        for (std::size_t i = 0; i < n; ++i) row[i] += step_y[i];
    }
}

// Float edge functions on 8-bit snapped corners with the top-left rule: the usual approach with
// single-precision vertex positions, evaluated at absolute pixel positions.
void edge_float(std::span<const glm::dvec2> corners, Coverage& target) {
    const std::size_t n = corners.size();
    if (n < 3 || n > kMaxCorners || !finite(corners)) return;
    std::array<glm::vec2, kMaxCorners> v{};
    float min_x = std::numeric_limits<float>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
    float area = 0.0F;
    for (std::size_t i = 0; i < n; ++i) {
        v[i] = {static_cast<float>(std::floor(corners[i].x * 256.0 + 0.5) / 256.0),
                static_cast<float>(std::floor(corners[i].y * 256.0 + 0.5) / 256.0)};
        min_x = std::min(min_x, v[i].x), max_x = std::max(max_x, v[i].x);
        min_y = std::min(min_y, v[i].y), max_y = std::max(max_y, v[i].y);
    }
    for (std::size_t i = 0; i < n; ++i) area += v[i].x * v[(i + 1) % n].y - v[(i + 1) % n].x * v[i].y;
    if (area == 0.0F) return;
    if (area < 0.0F) std::reverse(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n));
    const auto box = clipped_box(min_x, min_y, max_x, max_y, target);
    if (!box) return;
    for (std::int64_t y = box->y0; y <= box->y1; ++y) {
        for (std::int64_t x = box->x0; x <= box->x1; ++x) {
            const glm::vec2 p{static_cast<float>(x), static_cast<float>(y)};
            bool inside = true;
            for (std::size_t i = 0; i < n && inside; ++i) {
                const glm::vec2 a = v[i], b = v[(i + 1) % n];
                const float side = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
                const bool top_left = b.y < a.y || (b.y == a.y && b.x > a.x);
                inside = side > 0.0F || (side == 0.0F && top_left);
            }
            if (inside) target.hit(x, y);
        }
    }
}

// Scanline edge walking in doubles on 8-bit snapped corners: each row's span runs from the left
// crossing to the right one, ceil(left) to ceil(right) - 1, the top-left rule's scanline form.
void scanline_float(std::span<const glm::dvec2> corners, Coverage& target) {
    const std::size_t n = corners.size();
    if (n < 3 || n > kMaxCorners || !finite(corners)) return;
    std::array<glm::dvec2, kMaxCorners> v{};
    double min_y = std::numeric_limits<double>::max(), max_y = -min_y;
    for (std::size_t i = 0; i < n; ++i) {
        v[i] = {std::floor(corners[i].x * 256.0 + 0.5) / 256.0, std::floor(corners[i].y * 256.0 + 0.5) / 256.0};
        min_y = std::min(min_y, v[i].y), max_y = std::max(max_y, v[i].y);
    }
    const PixelRect& r = target.rect();
    const auto first = std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(min_y)), r.y);
    const auto last = std::min<std::int64_t>(static_cast<std::int64_t>(std::ceil(max_y)) - 1,
                                             std::int64_t{r.y} + r.height - 1);
    for (std::int64_t y = first; y <= last; ++y) {
        const double row = static_cast<double>(y);
        double left = std::numeric_limits<double>::max(), right = -left;
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 a = v[i], b = v[(i + 1) % n];
            if (a.y == b.y) continue;
            const glm::dvec2 top = a.y < b.y ? a : b, bottom = a.y < b.y ? b : a;
            if (row < top.y || row >= bottom.y) continue;  // rows from the top vertex, not the bottom
            const double x = top.x + (row - top.y) * (bottom.x - top.x) / (bottom.y - top.y);
            left = std::min(left, x), right = std::max(right, x);
        }
        if (left > right) continue;
        target.hit_row(y, static_cast<std::int64_t>(std::ceil(left)), static_cast<std::int64_t>(std::ceil(right)));
    }
}

// The product: exact 64-bit edge functions on 8-bit corners, solved for each row's span.
void span_exact(std::span<const glm::dvec2> corners, Coverage& target) {
    std::array<raster::SubpixelPoint, kMaxCorners> snapped{};
    if (corners.size() > kMaxCorners) return;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const auto point = raster::snap_to_subpixel(corners[i]);
        if (!point) return;
        snapped[i] = *point;
    }
    raster::rasterize_convex(std::span(snapped.data(), corners.size()), target.rect(),
                             [&target](raster::Span span) { target.hit_row(span.y, span.x_begin, span.x_end); });
}

// Integer edge functions on 8x8 tiles: a tile fully inside every edge is hit whole, a tile fully
// outside one edge is skipped, and only the rest are tested pixel by pixel.
void blocked_fixed8(std::span<const glm::dvec2> corners, Coverage& target) {
    constexpr std::int64_t one = 256;
    constexpr std::int64_t tile = 8;
    constexpr double limit = double{raster::kMaxSubpixelCoordinate} * one;
    const std::size_t n = corners.size();
    if (n < 3 || n > kMaxCorners) return;
    std::array<std::int64_t, kMaxCorners> xs{}, ys{};
    for (std::size_t i = 0; i < n; ++i) {
        const double x = std::floor(corners[i].x * one + 0.5), y = std::floor(corners[i].y * one + 0.5);
        if (!(std::abs(x) <= limit && std::abs(y) <= limit)) return;
        xs[i] = static_cast<std::int64_t>(x), ys[i] = static_cast<std::int64_t>(y);
    }
    std::int64_t area = 0;
    for (std::size_t i = 0; i < n; ++i) area += xs[i] * ys[(i + 1) % n] - xs[(i + 1) % n] * ys[i];
    if (area == 0) return;
    std::array<std::int64_t, kMaxCorners> sx{}, sy{}, off{};
    for (std::size_t i = 0; i < n; ++i) {
        std::size_t a = i, b = (i + 1) % n;
        if (area < 0) std::swap(a, b);
        const std::int64_t ex = xs[b] - xs[a], ey = ys[b] - ys[a];
        const bool top_left = ey < 0 || (ey == 0 && ex > 0);
        sx[i] = -ey * one, sy[i] = ex * one, off[i] = ey * xs[a] - ex * ys[a] - (top_left ? 0 : 1);
    }
    const auto [min_x, max_x] = std::minmax_element(xs.begin(), xs.begin() + static_cast<std::ptrdiff_t>(n));
    const auto [min_y, max_y] = std::minmax_element(ys.begin(), ys.begin() + static_cast<std::ptrdiff_t>(n));
    const auto box = clipped_box(static_cast<double>(*min_x) / one, static_cast<double>(*min_y) / one,
                                 static_cast<double>(*max_x) / one, static_cast<double>(*max_y) / one, target);
    if (!box) return;
    for (std::int64_t ty = box->y0; ty <= box->y1; ty += tile) {
        const std::int64_t ty1 = std::min(ty + tile - 1, box->y1);
        for (std::int64_t tx = box->x0; tx <= box->x1; tx += tile) {
            const std::int64_t tx1 = std::min(tx + tile - 1, box->x1);
            bool all_inside = true, skip = false;
            for (std::size_t i = 0; i < n && !skip; ++i) {
                // A linear function takes its extremes over a box at the box's corners.
                const std::int64_t base = off[i] + sy[i] * (sy[i] > 0 ? ty : ty1);
                const std::int64_t low = base + sx[i] * (sx[i] > 0 ? tx : tx1);
                const std::int64_t high = off[i] + sy[i] * (sy[i] > 0 ? ty1 : ty) + sx[i] * (sx[i] > 0 ? tx1 : tx);
                skip = high < 0;
                all_inside &= low >= 0;
            }
            if (skip) continue;
            for (std::int64_t y = ty; y <= ty1; ++y) {
                if (all_inside) {
                    target.hit_row(y, tx, tx1 + 1);
                    continue;
                }
                for (std::int64_t x = tx; x <= tx1; ++x) {
                    bool inside = true;
                    for (std::size_t i = 0; i < n; ++i) inside &= sx[i] * x + sy[i] * y + off[i] >= 0;
                    if (inside) target.hit(x, y);
                }
            }
        }
    }
}

constexpr std::array<FillMethod, 7> kFillMethods{{
    {"seed-bbox-float", "seed: bbox + float on whole pixels", seed_bbox_float, false},
    {"edge-float", "float edge functions (8-bit)", edge_float, false},
    {"edge-fixed4", "integer edge functions (4-bit)", edge_fixed<4>, false},
    {"edge-fixed8", "integer edge functions (8-bit)", edge_fixed<8>, false},
    {"blocked-fixed8", "8x8 blocks (8-bit)", blocked_fixed8, false},
    {"scanline-float", "double scanline (8-bit)", scanline_float, false},
    {"span-exact8", "exact spans (8-bit): product", span_exact, true},
}};

}  // namespace

std::span<const FillMethod> fill_methods() { return kFillMethods; }

const FillMethod& product_fill() { return kFillMethods.back(); }

}  // namespace lab
