#include <raster/lighting.hpp>

#include <raster/mesh.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raster {

Lighting::Lighting(const Material& surface, std::span<const DirectionalLight> sources, glm::vec3 to_eye)
    : material(surface) {
    if (material.shininess && !(*material.shininess >= 0.0F)) material.shininess = 0.0F;  // pow(0, -s) is infinite
    constexpr float kLargestWholeShininess = 4096.0F;
    if (material.shininess && *material.shininess >= 0.0F && *material.shininess <= kLargestWholeShininess &&
        std::floor(*material.shininess) == *material.shininess) {
        whole_shininess_ = static_cast<unsigned>(*material.shininess);
    }
    for (const DirectionalLight& light : sources) {
        const glm::vec3 toward = unit_or_zero(light.toward);
        const bool usable = toward != glm::vec3(0.0F) && std::isfinite(light.intensity);
        lights.push_back({usable ? toward : glm::vec3(0.0F), usable ? unit_or_zero(toward + to_eye) : glm::vec3(0.0F),
                          usable ? light.intensity : 0.0F});
    }
}

}  // namespace raster
