#pragma once

#include <raster/image/lanes.hpp>
#include <raster/shade/intensity_lighting.hpp>

#include <limits>
#include <optional>
#include <experimental/simd>

// The SIMD side of lanes (raster/image/lanes.hpp), GCC's <experimental/simd> at the baseline of
// the build (SSE2 on any x86-64): every function does per lane what its scalar namesake does.
namespace raster::lanes {

namespace stdx = std::experimental;
using Floats = stdx::fixed_size_simd<float, kLanes>;
using Mask = Floats::mask_type;

[[nodiscard]] inline Floats load(const LaneFloats& from) noexcept { return {from.data(), stdx::element_aligned}; }
inline void store(const Floats& value, LaneFloats& to) noexcept { value.copy_to(to.data(), stdx::element_aligned); }

struct Vec3 {
    Floats x, y, z;
};
[[nodiscard]] inline Vec3 load(const LaneVec3& from) noexcept { return {load(from.x), load(from.y), load(from.z)}; }
[[nodiscard]] inline Vec3 broadcast(float x, float y, float z) noexcept { return {Floats(x), Floats(y), Floats(z)}; }
[[nodiscard]] inline Vec3 operator+(const Vec3& a, const Vec3& b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
[[nodiscard]] inline Vec3 operator-(const Vec3& a, const Vec3& b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
[[nodiscard]] inline Vec3 operator/(const Vec3& a, const Floats& k) noexcept { return {a.x / k, a.y / k, a.z / k}; }
// glm::dot's order: (x x' + y y') + z z'.
[[nodiscard]] inline Floats dot(const Vec3& a, const Vec3& b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }

// std::max(0.0F, v): v where 0 < v, else 0 (NaN too).
[[nodiscard]] inline Floats positive_part(const Floats& v) noexcept {
    Floats out(0.0F);
    stdx::where(v > 0.0F, out) = v;
    return out;
}

// unit_or_zero per lane.
[[nodiscard]] inline Vec3 unit_or_zero(const Vec3& v) noexcept {
    const Floats squared = dot(v, v);
    const Mask usable = squared > 0.0F && squared < Floats(std::numeric_limits<float>::infinity());
    Floats length(1.0F);
    stdx::where(usable, length) = stdx::sqrt(squared);
    Vec3 out = v / length;
    stdx::where(!usable, out.x) = 0.0F;
    stdx::where(!usable, out.y) = 0.0F;
    stdx::where(!usable, out.z) = 0.0F;
    return out;
}

// SpecularPower per lane: repeated squaring for a whole exponent, std::pow otherwise.
[[nodiscard]] inline Floats powered(const SpecularPower& power, Floats cosine) noexcept {
    if (const std::optional<unsigned> whole = power.whole()) {
        Floats result(1.0F);
        for (unsigned n = *whole; n != 0; n >>= 1U, cosine *= cosine) {
            if ((n & 1U) != 0) result *= cosine;
        }
        return result;
    }
    Floats result;
    for (std::size_t i = 0; i < Floats::size(); ++i) result[i] = power(cosine[i]);
    return result;
}

}  // namespace raster::lanes
