#include <raster/shade/intensity_lighting.hpp>

#include "shade/simd_lanes.hpp"

// IntensityLighting::intensity in lanes: the scalar steps in their order, so each lane is exact.
namespace raster {

// Flattened, like LinearLighting::shade_lanes: the eight-lane helpers cost more called than inlined.
[[gnu::flatten]] void IntensityLighting::intensity_lanes(const LaneVec3& normals, LaneFloats& out,
                                                         int count) const noexcept {
    using lanes::Floats;
    namespace stdx = lanes::stdx;
    const lanes::Vec3 normal = lanes::unit_or_zero(lanes::load(normals));
    Floats lit(0.0F);
    for (const PreparedLight& light : lights) {
        Floats received =
            lanes::positive_part(lanes::dot(normal, lanes::broadcast(light.toward.x, light.toward.y, light.toward.z)));
        if (specular_.enabled()) {
            received += lanes::powered(
                specular_,
                lanes::positive_part(lanes::dot(normal, lanes::broadcast(light.half.x, light.half.y, light.half.z))));
        }
        lit += light.intensity * received;
    }
    Floats result = material.ambient + material.diffuse * lit;
    stdx::where(lanes::dot(normal, normal) == 0.0F, result) = material.ambient;  // no normal: no direct light
    LaneFloats all;
    lanes::store(result, all);
    for (int i = 0; i < count; ++i) out[static_cast<std::size_t>(i)] = all[static_cast<std::size_t>(i)];
}

void scaled_colours(Rgb base, const LaneFloats& intensity, std::span<Rgb> out) noexcept {
    using lanes::Floats;
    namespace stdx = lanes::stdx;
    using Ints = stdx::fixed_size_simd<int, kLanes>;
    const Floats scale = lanes::load(intensity);
    const auto channel = [&scale](std::uint8_t c) {
        Floats v = static_cast<float>(c) * scale;
        stdx::where(!(v > 0.0F), v) = 0.0F;  // negative or NaN
        stdx::where(v >= 255.0F, v) = 255.0F;
        Floats whole = stdx::static_simd_cast<Floats>(stdx::static_simd_cast<Ints>(v));  // truncation is floor here
        stdx::where(v - whole >= 0.5F, whole) += 1.0F;
        return whole;
    };
    const Floats r = channel(base.r), g = channel(base.g), b = channel(base.b);
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = {static_cast<std::uint8_t>(r[i]), static_cast<std::uint8_t>(g[i]), static_cast<std::uint8_t>(b[i])};
    }
}

}  // namespace raster
