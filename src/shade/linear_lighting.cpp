#include <raster/shade/linear_lighting.hpp>

#include <raster/geometry/mesh.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raster {
namespace {

bool usable(const Falloff& f) noexcept {
    const bool finite = std::isfinite(f.constant) && std::isfinite(f.linear) && std::isfinite(f.quadratic);
    const bool non_negative = f.constant >= 0.0F && f.linear >= 0.0F && f.quadratic >= 0.0F;
    // With no constant term the light is still finite away from it, but it must fall off somehow.
    return finite && non_negative && (f.constant > 0.0F || f.linear > 0.0F || f.quadratic > 0.0F);
}

bool usable(const PointLight& light) noexcept {
    const glm::vec3& p = light.position;
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(light.intensity) &&
           usable(light.falloff);
}

}  // namespace

LinearMaterial LinearMaterial::from_srgb(Rgb emissive, Rgb diffuse, Rgb specular, std::optional<float> shininess) {
    return {linear_from_srgb(emissive), linear_from_srgb(diffuse), linear_from_srgb(specular), shininess};
}

LinearLighting::LinearLighting(const LinearMaterial& material, std::span<const DirectionalLight> directional,
                               std::span<const PointLight> points, glm::vec3 to_eye,
                               std::optional<glm::vec3> eye_position, std::optional<DepthDarkening> darkening)
    : material_(material), to_eye_(unit_or_zero(to_eye)), eye_(eye_position), power_(material.shininess),
      darkening_(darkening) {
    for (const DirectionalLight& light : directional) {
        PreparedLight ready = prepare_light(light, to_eye_);
        ready.intensity = std::clamp(ready.intensity, -kBrightest, kBrightest);
        if (ready.intensity != 0.0F) directional_.push_back(ready);
    }
    for (const PointLight& light : points) {
        if (usable(light) && light.intensity != 0.0F)
            points_.push_back({light.position, light.intensity, light.falloff});
    }
}

LinearLighting::Toward LinearLighting::toward_point_precisely(glm::vec3 light, glm::vec3 surface) noexcept {
    // In double the offset of two finite floats neither overflows nor underflows; the distance
    // may still round to infinity as a float, and then the falloff (if any) takes the light to 0.
    const glm::dvec3 offset = glm::dvec3(light) - glm::dvec3(surface);
    const double distance = glm::length(offset);
    if (!(distance > 0.0) || !std::isfinite(distance)) return {glm::vec3(0.0F), 0.0F};
    return {glm::vec3(offset / distance), static_cast<float>(distance)};
}

}  // namespace raster
