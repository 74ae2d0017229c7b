#include <raster/shade/lighting.hpp>

#include "shade/simd_lanes.hpp"

// Lighting::intensity in lanes: the scalar steps in their order, so each lane is exact.
namespace raster {

// Flattened, like LinearLighting::shade_lanes: the eight-lane helpers cost more called than inlined.
[[gnu::flatten]] void Lighting::intensity_lanes(const LaneVec3& normals, LaneFloats& out, int count) const noexcept {
    using lanes::Floats;
    namespace stdx = lanes::stdx;
    const lanes::Vec3 normal = lanes::unit_or_zero(lanes::load(normals));
    Floats lit(0.0F);
    for (const PreparedLight& light : lights) {
        Floats received = lanes::positive_part(lanes::dot(normal, lanes::broadcast(light.toward.x, light.toward.y, light.toward.z)));
        if (specular_.enabled()) {
            received += lanes::powered(specular_, lanes::positive_part(lanes::dot(normal, lanes::broadcast(light.half.x, light.half.y, light.half.z))));
        }
        lit += light.intensity * received;
    }
    Floats result = material.ambient + material.diffuse * lit;
    stdx::where(lanes::dot(normal, normal) == 0.0F, result) = material.ambient;  // no normal: no direct light
    LaneFloats all;
    lanes::store(result, all);
    for (int i = 0; i < count; ++i) out[static_cast<std::size_t>(i)] = all[static_cast<std::size_t>(i)];
}

}  // namespace raster
