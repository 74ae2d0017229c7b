#include <raster/shade/metallic_roughness.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace raster {
namespace {

float unit_or(float value, float fallback) noexcept {
    return std::isnan(value) ? fallback : std::clamp(value, 0.0F, 1.0F);
}

float light_or_zero(float value) noexcept {
    return std::isnan(value) ? 0.0F : std::clamp(value, 0.0F, std::numeric_limits<float>::max());
}

}  // namespace

MetallicRoughness MetallicRoughness::usable() const noexcept {
    MetallicRoughness out = *this;
    out.base_colour = {unit_or(base_colour.r, 1.0F), unit_or(base_colour.g, 1.0F), unit_or(base_colour.b, 1.0F)};
    out.metallic = unit_or(metallic, 1.0F);
    out.roughness = unit_or(roughness, 1.0F);
    out.occlusion_strength = unit_or(occlusion_strength, 1.0F);
    out.emissive = {light_or_zero(emissive.r), light_or_zero(emissive.g), light_or_zero(emissive.b)};
    out.normal_scale = std::isfinite(normal_scale) ? normal_scale : 1.0F;
    return out;
}

}  // namespace raster
