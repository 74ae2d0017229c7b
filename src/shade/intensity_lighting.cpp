#include <raster/shade/intensity_lighting.hpp>

#include <raster/geometry/mesh.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raster {

SpecularPower::SpecularPower(std::optional<float> shininess) noexcept {
    if (!shininess) return;
    exponent_ = *shininess >= 0.0F ? *shininess : 0.0F;  // also NaN to 0
    constexpr float kLargestWholeShininess = 4096.0F;
    if (*exponent_ <= kLargestWholeShininess && std::floor(*exponent_) == *exponent_)
        whole_ = static_cast<unsigned>(*exponent_);
}

PreparedLight prepare_light(const DirectionalLight& light, glm::vec3 to_eye) noexcept {
    const glm::vec3 toward = unit_or_zero(light.toward);
    if (toward == glm::vec3(0.0F) || !std::isfinite(light.intensity)) return {glm::vec3(0.0F), glm::vec3(0.0F), 0.0F};
    return {toward, unit_or_zero(toward + to_eye), light.intensity};
}

IntensityLighting::IntensityLighting(const IntensityMaterial& surface, std::span<const DirectionalLight> sources,
                                     glm::vec3 to_eye)
    : material(surface), specular_(surface.shininess) {
    if (material.shininess && !(*material.shininess >= 0.0F)) material.shininess = 0.0F;  // pow(0, -s) is infinite
    for (const DirectionalLight& light : sources) lights.push_back(prepare_light(light, to_eye));
}

}  // namespace raster
