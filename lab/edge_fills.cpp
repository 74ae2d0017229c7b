#include "fill_kernels.hpp"

#include <raster/image/subpixel.hpp>

#include <array>

// The integer edge-function fills: pixel by pixel, and on 8x8 blocks.
namespace lab::kernels {
namespace {

// A polygon's corners snapped to 1/2^Bits pixel as edge functions E(x, y) = step_x x + step_y y +
// offset, oriented and biased (top-left rule) so that a pixel centre is inside when every E >= 0.
template <int Bits>
struct FixedEdges {
    std::size_t count = 0;
    std::array<std::int64_t, kMaxCorners> step_x{}, step_y{}, offset{};
    Box box{};

    std::int64_t at(std::size_t i, std::int64_t x, std::int64_t y) const {
        return step_x[i] * x + step_y[i] * y + offset[i];
    }

    // Nothing for non-finite or far corners, zero area, or no pixel centre of the target inside.
    static std::optional<FixedEdges> set_up(std::span<const glm::dvec2> corners, const Coverage& target) {
        constexpr std::int64_t one = std::int64_t{1} << Bits;
        constexpr double limit = double{raster::kMaxSubpixelCoordinate} * one;
        FixedEdges edges;
        edges.count = corners.size();
        const std::size_t n = edges.count;
        if (n < 3 || n > kMaxCorners) return std::nullopt;
        std::array<std::int64_t, kMaxCorners> xs{}, ys{};
        for (std::size_t i = 0; i < n; ++i) {
            const double x = std::floor(corners[i].x * one + 0.5), y = std::floor(corners[i].y * one + 0.5);
            if (!(std::abs(x) <= limit && std::abs(y) <= limit)) return std::nullopt;
            xs[i] = static_cast<std::int64_t>(x), ys[i] = static_cast<std::int64_t>(y);
        }
        std::int64_t area = 0;
        for (std::size_t i = 0; i < n; ++i) area += xs[i] * ys[(i + 1) % n] - xs[(i + 1) % n] * ys[i];
        if (area == 0) return std::nullopt;
        for (std::size_t i = 0; i < n; ++i) {
            std::size_t a = i, b = (i + 1) % n;
            if (area < 0) std::swap(a, b);
            const std::int64_t ex = xs[b] - xs[a], ey = ys[b] - ys[a];
            const bool top_left = ey < 0 || (ey == 0 && ex > 0);
            edges.step_x[i] = -ey * one;
            edges.step_y[i] = ex * one;
            edges.offset[i] = ey * xs[a] - ex * ys[a] - (top_left ? 0 : 1);
        }
        const auto end = static_cast<std::ptrdiff_t>(n);
        const auto [min_x, max_x] = std::minmax_element(xs.begin(), xs.begin() + end);
        const auto [min_y, max_y] = std::minmax_element(ys.begin(), ys.begin() + end);
        const auto box = clipped_box(static_cast<double>(*min_x) / one, static_cast<double>(*min_y) / one,
                                     static_cast<double>(*max_x) / one, static_cast<double>(*max_y) / one, target);
        if (!box) return std::nullopt;
        edges.box = *box;
        return edges;
    }
};

// One pixel at a time with incremental steps across each row.
template <int Bits>
void edge_fixed(std::span<const glm::dvec2> corners, Coverage& target) {
    const auto edges = FixedEdges<Bits>::set_up(corners, target);
    if (!edges) return;
    const std::size_t n = edges->count;
    const Box& box = edges->box;
    for (std::int64_t y = box.y0; y <= box.y1; ++y) {
        std::array<std::int64_t, kMaxCorners> value{};
        for (std::size_t i = 0; i < n; ++i) value[i] = edges->at(i, box.x0, y);
        for (std::int64_t x = box.x0; x <= box.x1; ++x) {
            bool inside = true;
            for (std::size_t i = 0; i < n; ++i) {
                inside &= value[i] >= 0;
                value[i] += edges->step_x[i];
            }
            if (inside) target.hit(x, y);
        }
    }
}

}  // namespace

void edge_fixed4(std::span<const glm::dvec2> corners, Coverage& target) { edge_fixed<4>(corners, target); }
void edge_fixed8(std::span<const glm::dvec2> corners, Coverage& target) { edge_fixed<8>(corners, target); }

// On 8x8 tiles: a tile fully inside every edge is hit whole, a tile fully outside one edge is
// skipped, and only the rest are tested pixel by pixel.
void blocked_fixed8(std::span<const glm::dvec2> corners, Coverage& target) {
    constexpr std::int64_t tile = 8;
    const auto edges = FixedEdges<8>::set_up(corners, target);
    if (!edges) return;
    const std::size_t n = edges->count;
    const Box& box = edges->box;
    for (std::int64_t ty = box.y0; ty <= box.y1; ty += tile) {
        const std::int64_t ty1 = std::min(ty + tile - 1, box.y1);
        for (std::int64_t tx = box.x0; tx <= box.x1; tx += tile) {
            const std::int64_t tx1 = std::min(tx + tile - 1, box.x1);
            bool all_inside = true, skip = false;
            for (std::size_t i = 0; i < n && !skip; ++i) {
                // A linear function takes its extremes over a box at the box's corners.
                const bool rises_x = edges->step_x[i] > 0, rises_y = edges->step_y[i] > 0;
                const std::int64_t low = edges->at(i, rises_x ? tx : tx1, rises_y ? ty : ty1);
                const std::int64_t high = edges->at(i, rises_x ? tx1 : tx, rises_y ? ty1 : ty);
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
                    for (std::size_t i = 0; i < n; ++i) inside &= edges->at(i, x, y) >= 0;
                    if (inside) target.hit(x, y);
                }
            }
        }
    }
}

}  // namespace lab::kernels
