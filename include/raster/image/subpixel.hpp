#pragma once

#include <cstdint>
#include <optional>
#include <glm/vec2.hpp>

namespace raster {

// Screen positions are fixed point with this many fractional bits (doc/conventions.md#pixels).
inline constexpr int kSubpixelBits = 8;
inline constexpr std::int32_t kSubpixelOne = 1 << kSubpixelBits;
// Positions farther than this many pixels from the origin are rejected, which keeps every edge
// function of the fill exact in 64 bits.
inline constexpr std::int32_t kMaxSubpixelCoordinate = 1 << 21;

// A screen position in units of 1/kSubpixelOne pixel; pixel centres sit on multiples of kSubpixelOne.
struct SubpixelPoint {
    std::int32_t x;
    std::int32_t y;

    friend constexpr bool operator==(SubpixelPoint, SubpixelPoint) = default;
};

// Snaps continuous pixel coordinates to the nearest subpixel (halves up). NaN, infinities and
// positions beyond kMaxSubpixelCoordinate give nothing.
[[nodiscard]] std::optional<SubpixelPoint> snap_to_subpixel(glm::dvec2 screen) noexcept;

// The pixel whose centre is nearest (halves up), for primitives that work on whole pixels.
[[nodiscard]] constexpr glm::ivec2 nearest_pixel(SubpixelPoint point) noexcept {
    constexpr std::int32_t half = kSubpixelOne / 2;
    return {(point.x + half) >> kSubpixelBits, (point.y + half) >> kSubpixelBits};
}

}  // namespace raster
