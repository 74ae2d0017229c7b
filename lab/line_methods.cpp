#include "line_methods.hpp"

#include <raster/rasterize/line.hpp>

#include <array>
#include <cmath>
#include <cstdlib>

namespace lab {
namespace {

constexpr raster::Rgb kInk{255, 255, 255};

// The seed (0.0.2): t = i / N in single precision, each sample rounded half away from zero.
std::int64_t seed_float_dda(raster::Framebuffer& target, glm::ivec2 origin, glm::ivec2 from, glm::ivec2 to) {
    const float dx = static_cast<float>(to.x) - static_cast<float>(from.x);
    const float dy = static_cast<float>(to.y) - static_cast<float>(from.y);
    const auto steps = static_cast<std::int64_t>(std::max(std::abs(dx), std::abs(dy)));
    for (std::int64_t i = 0; i <= steps; ++i) {
        const float t = steps == 0 ? 0.0F : static_cast<float>(i) / static_cast<float>(steps);
        const float x = std::round(static_cast<float>(from.x) + dx * t);
        const float y = std::round(static_cast<float>(from.y) + dy * t);
        target.set_pixel(static_cast<int>(static_cast<std::int64_t>(x) - origin.x),
                         static_cast<int>(static_cast<std::int64_t>(y) - origin.y), kInk);
    }
    return steps + 1;
}

// Classic Bresenham over every step, both ends included.
std::int64_t bresenham(raster::Framebuffer& target, glm::ivec2 origin, glm::ivec2 from, glm::ivec2 to) {
    const std::int64_t dx = std::abs(std::int64_t{to.x} - from.x), dy = -std::abs(std::int64_t{to.y} - from.y);
    const std::int64_t sx = from.x < to.x ? 1 : -1, sy = from.y < to.y ? 1 : -1;
    std::int64_t error = dx + dy, x = from.x, y = from.y, steps = 0;
    while (true) {
        ++steps;
        target.set_pixel(static_cast<int>(x - origin.x), static_cast<int>(y - origin.y), kInk);
        if (x == to.x && y == to.y) return steps;
        const std::int64_t twice = 2 * error;
        if (twice >= dy) {
            error += dy;
            x += sx;
        }
        if (twice <= dx) {
            error += dx;
            y += sy;
        }
    }
}

// The product: exact integer DDA that walks only the visible samples.
std::int64_t integer_dda(raster::Framebuffer& target, glm::ivec2 origin, glm::ivec2 from, glm::ivec2 to) {
    return raster::draw_line(target, from, to, kInk, origin);
}

constexpr std::array<LineMethod, 3> kLineMethods{{
    {"seed-float-dda", "seed: float DDA", seed_float_dda, false},
    {"bresenham", "Bresenham", bresenham, false},
    {"integer-dda", "exact integer DDA: product", integer_dda, true},
}};

}  // namespace

std::span<const LineMethod> line_methods() { return kLineMethods; }

const LineMethod& product_line() { return kLineMethods.back(); }

}  // namespace lab
