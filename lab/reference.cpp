#include "reference.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace lab {
namespace {

__extension__ using Exact = __int128;

Exact floor_div(Exact n, Exact d) {  // d > 0
    const Exact q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

}  // namespace

glm::dvec2 to_screen(ExactPoint point) {
    return {static_cast<double>(point.x) / kExactOne, static_cast<double>(point.y) / kExactOne};
}

void reference_polygon(std::span<const ExactPoint> corners, Coverage& target) {
    const std::size_t n = corners.size();
    Exact area = 0;
    for (std::size_t i = 0; i < n; ++i) {
        area += Exact{corners[i].x} * corners[(i + 1) % n].y - Exact{corners[(i + 1) % n].x} * corners[i].y;
    }
    if (area == 0) return;

    std::vector<ExactPoint> ring(corners.begin(), corners.end());
    if (area < 0) std::reverse(ring.begin(), ring.end());
    // Only pixel centres inside the bounding box can be covered.
    const PixelRect& rect = target.rect();
    std::int64_t min_x = ring[0].x, max_x = ring[0].x, min_y = ring[0].y, max_y = ring[0].y;
    for (const ExactPoint& p : ring) {
        min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
        min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
    const auto first_i = std::max<std::int64_t>(rect.x, -static_cast<std::int64_t>(floor_div(-min_x, kExactOne)));
    const auto last_i = std::min<std::int64_t>(std::int64_t{rect.x} + rect.width - 1,
                                               static_cast<std::int64_t>(floor_div(max_x, kExactOne)));
    const auto first_j = std::max<std::int64_t>(rect.y, -static_cast<std::int64_t>(floor_div(-min_y, kExactOne)));
    const auto last_j = std::min<std::int64_t>(std::int64_t{rect.y} + rect.height - 1,
                                               static_cast<std::int64_t>(floor_div(max_y, kExactOne)));
    for (std::int64_t j = first_j; j <= last_j; ++j) {
        for (std::int64_t i = first_i; i <= last_i; ++i) {
            const Exact px = Exact{i} * kExactOne;
            const Exact py = Exact{j} * kExactOne;
            bool inside = true;
            for (std::size_t k = 0; k < n && inside; ++k) {
                const ExactPoint a = ring[k];
                const ExactPoint b = ring[(k + 1) % n];
                const Exact ex = b.x - a.x;
                const Exact ey = b.y - a.y;
                if (ex == 0 && ey == 0) continue;  // a repeated corner is no edge
                const Exact side = ex * (py - a.y) - ey * (px - a.x);
                const bool top_left = ey < 0 || (ey == 0 && ex > 0);
                inside = side > 0 || (side == 0 && top_left);
            }
            if (inside) target.hit(i, j);
        }
    }
}

void reference_line(glm::ivec2 from, glm::ivec2 to, Coverage& target) {
    const std::int64_t dx = std::int64_t{to.x} - from.x;
    const std::int64_t dy = std::int64_t{to.y} - from.y;
    const std::int64_t steps = std::max(std::abs(dx), std::abs(dy));
    target.hit(to.x, to.y);  // the end pixel, which the diamond-exit rule leaves out
    for (std::int64_t k = 0; k < steps; ++k) {
        // Where the segment crosses the k-th pixel centre line of its major axis: minor / steps.
        if (std::abs(dx) >= std::abs(dy)) {
            const Exact y2 = 2 * (Exact{from.y} * steps + Exact{dy} * k);  // 2 * steps * y
            // The diamond at that column holds the row within 1/2; the shift (e, e) moves the
            // crossing by e * (1 - dy / dx) >= 0, so ties go to +y.
            const auto row = static_cast<std::int64_t>(floor_div(y2 + steps, 2 * Exact{steps}));
            target.hit(from.x + (dx > 0 ? k : -k), row);
        } else {
            // Shifting the segment by (e, e) moves its crossing by e * (1 - dx / dy) > 0: ties to +x.
            const Exact x2 = 2 * (Exact{from.x} * steps + Exact{dx} * k);
            const auto column = static_cast<std::int64_t>(floor_div(x2 + steps, 2 * Exact{steps}));
            target.hit(column, from.y + (dy > 0 ? k : -k));
        }
    }
}

}  // namespace lab
