#include <raster/mesh.hpp>

#include <cmath>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster {

glm::vec3 facet_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) noexcept {
    // Clockwise from outside in a left-handed world: (b - a) x (c - b) points outward.
    return unit_or_zero(glm::cross(b - a, c - b));
}

Facet facet_facing_away(const std::vector<glm::vec3>& positions, std::uint32_t a, std::uint32_t b,
                        std::uint32_t c, glm::vec3 inside) {
    Facet facet{{a, b, c}, facet_normal(positions[a], positions[b], positions[c])};
    const glm::vec3 centre = (positions[a] + positions[b] + positions[c]) / 3.0F;
    if (glm::dot(facet.normal, centre - inside) < 0.0F) {
        std::swap(facet.corners[1], facet.corners[2]);
        facet.normal = -facet.normal;
    }
    return facet;
}

Mesh posed(const Mesh& mesh, const glm::mat4& model) { return posed(mesh, model, PoseParts{}); }

Mesh posed(const Mesh& mesh, const glm::mat4& model, PoseParts parts) {
    const glm::mat3 linear(model);
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
    Mesh result;
    result.surface = mesh.surface;
    result.convex = mesh.convex;
    result.positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) result.positions.push_back(glm::vec3(model * glm::vec4(p, 1.0F)));
    result.uvs = mesh.uvs;
    if (parts.vertex_normals) {
        result.normals.reserve(mesh.normals.size());
        for (const glm::vec3& n : mesh.normals) result.normals.push_back(unit_or_zero(normal_matrix * n));
    } else {
        result.normals.resize(mesh.normals.size());
    }
    // A mirror turns clockwise into counter-clockwise: swap two corners to keep the convention.
    const bool mirrored = glm::determinant(linear) < 0.0F;
    result.facets.reserve(mesh.facets.size());
    for (Facet facet : mesh.facets) {
        if (mirrored) std::swap(facet.corners[1], facet.corners[2]);
        facet.normal = parts.facet_normals ? unit_or_zero(normal_matrix * facet.normal) : glm::vec3(0.0F);
        result.facets.push_back(facet);
    }
    return result;
}

}  // namespace raster
