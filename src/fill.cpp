#include <raster/fill.hpp>

#include <algorithm>
#include <cstdlib>

namespace raster {
namespace {

// The signed 2D cross product (b - a) x (p - a) as a linear function of the pixel (x, y).
struct EdgeFunction {
    std::int64_t dx_step;  // change per pixel to the right
    std::int64_t dy_step;  // change per pixel down
    std::int64_t at_origin;

    static EdgeFunction through(glm::ivec2 a, glm::ivec2 b) {
        const std::int64_t ex = std::int64_t{b.x} - a.x;
        const std::int64_t ey = std::int64_t{b.y} - a.y;
        return {-ey, ex, ey * a.x - ex * a.y};
    }
    std::int64_t at(std::int64_t x, std::int64_t y) const {
        return dx_step * x + dy_step * y + at_origin;
    }
    EdgeFunction negated() const { return {-dx_step, -dy_step, -at_origin}; }
};

bool within_fill_limits(const std::array<glm::ivec2, 4>& corners) {
    return std::all_of(corners.begin(), corners.end(), [](glm::ivec2 c) {
        return std::abs(c.x) <= kMaxFillCoordinate && std::abs(c.y) <= kMaxFillCoordinate;
    });
}

// Twice the signed area (shoelace); its sign tells the winding.
std::int64_t twice_signed_area(const std::array<glm::ivec2, 4>& corners) {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::ivec2 a = corners[i];
        const glm::ivec2 b = corners[(i + 1) % corners.size()];
        sum += std::int64_t{a.x} * b.y - std::int64_t{b.x} * a.y;
    }
    return sum;
}

}  // namespace

std::int64_t fill_quad(Framebuffer& framebuffer, const std::array<glm::ivec2, 4>& corners,
                       Rgb colour) {
    if (!within_fill_limits(corners)) return 0;
    const std::int64_t area = twice_signed_area(corners);
    if (area == 0) return 0;

    // Orient every edge so that the inside is where all four functions are >= 0.
    std::array<EdgeFunction, 4> edges{};
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const EdgeFunction edge = EdgeFunction::through(corners[i], corners[(i + 1) % 4]);
        edges[i] = area > 0 ? edge : edge.negated();
    }

    int min_x = corners[0].x, max_x = corners[0].x, min_y = corners[0].y, max_y = corners[0].y;
    for (const glm::ivec2 c : corners) {
        min_x = std::min(min_x, c.x);
        max_x = std::max(max_x, c.x);
        min_y = std::min(min_y, c.y);
        max_y = std::max(max_y, c.y);
    }
    min_x = std::max(min_x, 0);
    min_y = std::max(min_y, 0);
    max_x = std::min(max_x, framebuffer.width() - 1);
    max_y = std::min(max_y, framebuffer.height() - 1);
    if (min_x > max_x || min_y > max_y) return 0;

    for (int y = min_y; y <= max_y; ++y) {
        std::array<std::int64_t, 4> value{};
        for (std::size_t i = 0; i < edges.size(); ++i) value[i] = edges[i].at(min_x, y);
        for (int x = min_x; x <= max_x; ++x) {
            if (value[0] >= 0 && value[1] >= 0 && value[2] >= 0 && value[3] >= 0) {
                framebuffer.set_pixel(x, y, colour);
            }
            for (std::size_t i = 0; i < edges.size(); ++i) value[i] += edges[i].dx_step;
        }
    }
    return std::int64_t{max_x - min_x + 1} * (max_y - min_y + 1);
}

}  // namespace raster
