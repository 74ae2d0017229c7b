#pragma once

#include <raster/image/colour.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <glm/vec3.hpp>

// Pixels shaded in lanes: the rasterizer hands a shader up to kLanes pixels at once, their values
// side by side (one array per component), so that the arithmetic runs in SIMD registers.
// Each lane computes with the very operations of the one-pixel form, so pictures stay the same
// bit for bit (doc/conventions.md#lanes).
namespace raster {

inline constexpr int kLanes = 8;
using LaneFloats = std::array<float, kLanes>;

// kLanes vectors, one component per array.
struct LaneVec3 {
    LaneFloats x{};
    LaneFloats y{};
    LaneFloats z{};
};

// kLanes linear colours.
struct LaneRgb {
    LaneFloats r{};
    LaneFloats g{};
    LaneFloats b{};
};

// Lane i of `lanes` set to one value.
inline void put_lane(LaneVec3& lanes, std::size_t i, glm::vec3 v) noexcept {
    lanes.x[i] = v.x, lanes.y[i] = v.y, lanes.z[i] = v.z;
}
inline void put_lane(LaneRgb& lanes, std::size_t i, LinearRgb c) noexcept {
    lanes.r[i] = c.r, lanes.g[i] = c.g, lanes.b[i] = c.b;
}

// srgb_from_linear of lane i for the first out.size() lanes.
void srgb_from_linear(const LaneRgb& colours, std::span<Rgb> out) noexcept;

}  // namespace raster
