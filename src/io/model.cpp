#include <raster/io/model.hpp>

#include <algorithm>
#include <cmath>
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

std::size_t point_count(const Model& model) noexcept {
    std::size_t count = 0;
    for (const ModelPart& part : model.parts) count += part.mesh.points.size();
    return count;
}

std::size_t segment_count(const Model& model) noexcept {
    std::size_t count = 0;
    for (const ModelPart& part : model.parts) count += part.mesh.segments.size();
    return count;
}

namespace {

// Calls `visit` with every position a facet, point or segment of the model uses.
template <typename Visit>
void for_each_drawn_position(const Model& model, Visit&& visit) {
    for (const ModelPart& part : model.parts) {
        const std::vector<glm::vec3>& positions = part.mesh.positions;
        for (const Facet& facet : part.mesh.facets) {
            for (const std::uint32_t corner : facet.corners) visit(glm::dvec3(positions.at(corner)));
        }
        for (const std::uint32_t point : part.mesh.points) visit(glm::dvec3(positions.at(point)));
        for (const auto& segment : part.mesh.segments) {
            for (const std::uint32_t end : segment) visit(glm::dvec3(positions.at(end)));
        }
    }
}

}  // namespace

Bounds bounds_of(const Model& model) {
    constexpr double kHuge = std::numeric_limits<double>::max();
    Bounds bounds{glm::dvec3(kHuge), glm::dvec3(-kHuge), 0.0};
    bool any = false;
    for_each_drawn_position(model, [&](const glm::dvec3& p) {
        bounds.low = glm::min(bounds.low, p);
        bounds.high = glm::max(bounds.high, p);
        any = true;
    });
    if (!any) throw std::invalid_argument(kNothingToDraw);
    const glm::dvec3 centre = bounds.centre();
    double farthest = 0.0;  // squared: the root of the largest is the largest root, as rounded
    for_each_drawn_position(
        model, [&](const glm::dvec3& p) { farthest = std::max(farthest, glm::dot(p - centre, p - centre)); });
    bounds.radius = std::sqrt(farthest);
    return bounds;
}

}  // namespace raster
