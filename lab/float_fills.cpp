#include "fill_kernels.hpp"

#include <array>
#include <limits>

// The floating-point fills: the seed's, float edge functions and a double scanline.
namespace lab::kernels {

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
    const auto last =
        std::min<std::int64_t>(static_cast<std::int64_t>(std::ceil(max_y)) - 1, std::int64_t{r.y} + r.height - 1);
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

}  // namespace lab::kernels
