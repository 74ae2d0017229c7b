#include <raster/io/model.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <glm/geometric.hpp>

namespace raster {

LinearMaterial default_model_material() noexcept {
    return {LinearRgb{}, LinearRgb{0.8F, 0.8F, 0.8F}, LinearRgb{}, std::nullopt};
}

std::size_t triangle_count(const Model& model) noexcept {
    std::size_t count = 0;
    for (const ModelPart& part : model.parts) count += part.mesh.facets.size();
    return count;
}

Bounds bounds_of(const Model& model) {
    constexpr double kHuge = std::numeric_limits<double>::max();
    Bounds bounds{glm::dvec3(kHuge), glm::dvec3(-kHuge), 0.0};
    bool any = false;
    for (const ModelPart& part : model.parts) {
        for (const Facet& facet : part.mesh.facets) {
            for (const std::uint32_t corner : facet.corners) {
                const glm::dvec3 p = part.mesh.positions.at(corner);
                bounds.low = glm::min(bounds.low, p);
                bounds.high = glm::max(bounds.high, p);
                any = true;
            }
        }
    }
    if (!any) throw std::invalid_argument("model has no facets");
    const glm::dvec3 centre = bounds.centre();
    for (const ModelPart& part : model.parts) {
        for (const Facet& facet : part.mesh.facets) {
            for (const std::uint32_t corner : facet.corners) {
                bounds.radius = std::max(bounds.radius, glm::length(glm::dvec3(part.mesh.positions[corner]) - centre));
            }
        }
    }
    return bounds;
}

}  // namespace raster
