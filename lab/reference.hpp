#pragma once

#include "coverage.hpp"

#include <cstdint>
#include <span>
#include <glm/vec2.hpp>

// The yardstick: exact rasterization with no floating point in any coverage decision.
namespace lab {

// Every corpus position lies on a grid of 1/kExactOne pixel, so doubles carry it exactly.
inline constexpr int kExactBits = 10;
inline constexpr std::int64_t kExactOne = std::int64_t{1} << kExactBits;

struct ExactPoint {
    std::int64_t x;  // in 1/kExactOne pixel
    std::int64_t y;
};

[[nodiscard]] glm::dvec2 to_screen(ExactPoint point);

// Hits every pixel of the target whose centre (i, j) a convex polygon covers: strictly inside
// all edges, or exactly on a top or left edge. Zero area covers nothing.
void reference_polygon(std::span<const ExactPoint> corners, Coverage& target);

// Hits the pixels of the segment between two pixel centres by the diamond-exit rule, ties
// broken by moving the segment an infinitesimal (e, e) toward +x and +y, plus the end pixel
// (our lines include both ends).
void reference_line(glm::ivec2 from, glm::ivec2 to, Coverage& target);

}  // namespace lab
