#include <raster/geometry/tangents.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

namespace raster {
namespace {

// A unit vector perpendicular to n (or to z when n is zero): the tangent where texture
// coordinates give none.
glm::vec3 any_perpendicular(glm::vec3 n) noexcept {
    const glm::vec3 axis = std::abs(n.x) < 0.9F ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 across = unit_or_zero(axis - n * glm::dot(n, axis));
    return glm::dot(across, across) > 0.0F ? across : glm::vec3(1, 0, 0);
}

// The angle at corner a of the triangle a b c, 0 for a corner of no length.
float corner_angle(glm::vec3 a, glm::vec3 b, glm::vec3 c) noexcept {
    const glm::vec3 ab = unit_or_zero(b - a), ac = unit_or_zero(c - a);
    return std::acos(std::clamp(glm::dot(ab, ac), -1.0F, 1.0F));
}

}  // namespace

std::vector<glm::vec4> tangents_from_uvs(const Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    if (mesh.uvs.size() != n || n == 0) return {};
    const auto normal_at = [&](std::uint32_t i) {
        return mesh.normals.size() == n ? unit_or_zero(mesh.normals[i]) : glm::vec3(0.0F);
    };
    std::vector<glm::vec3> along_u(n, glm::vec3(0.0F)), along_v(n, glm::vec3(0.0F)), facing(n, glm::vec3(0.0F));
    for (const Facet& facet : mesh.facets) {
        const auto [i0, i1, i2] = facet.corners;
        if (i0 >= n || i1 >= n || i2 >= n) continue;
        const glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0], e2 = mesh.positions[i2] - mesh.positions[i0];
        const glm::vec2 d1 = mesh.uvs[i1] - mesh.uvs[i0], d2 = mesh.uvs[i2] - mesh.uvs[i0];
        // dP/du and dP/dv of the facet, each up to the common factor 1 / (d1 x d2), whose sign is kept.
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!(det != 0.0F) || !std::isfinite(det)) continue;  // texture coordinates along a line: no direction
        const float sign = det > 0.0F ? 1.0F : -1.0F;
        const glm::vec3 u = unit_or_zero((e1 * d2.y - e2 * d1.y) * sign);
        const glm::vec3 v = unit_or_zero((e2 * d1.x - e1 * d2.x) * sign);
        const std::array<std::uint32_t, 3> at{i0, i1, i2};
        for (std::size_t k = 0; k < 3; ++k) {
            // As MikkTSpace: each corner takes the facet's directions in its own normal's plane, weighted by its angle.
            const glm::vec3 normal = normal_at(at[k]);
            const float angle =
                corner_angle(mesh.positions[at[k]], mesh.positions[at[(k + 1) % 3]], mesh.positions[at[(k + 2) % 3]]);
            along_u[at[k]] += unit_or_zero(u - normal * glm::dot(normal, u)) * angle;
            along_v[at[k]] += unit_or_zero(v - normal * glm::dot(normal, v)) * angle;
            facing[at[k]] += unit_or_zero(facet.normal) * angle;
        }
    }
    std::vector<glm::vec4> tangents(n);
    for (std::size_t i = 0; i < n; ++i) {
        glm::vec3 normal = normal_at(static_cast<std::uint32_t>(i));
        // Without a vertex normal, the facets' decide the handedness, as the shader then leans theirs.
        if (!(glm::dot(normal, normal) > 0.0F)) normal = unit_or_zero(facing[i]);
        // Gram-Schmidt: the u direction less its part along the normal.
        glm::vec3 t = unit_or_zero(along_u[i] - normal * glm::dot(normal, along_u[i]));
        if (!(glm::dot(t, t) > 0.0F)) t = any_perpendicular(normal);
        const float handed = glm::dot(glm::cross(normal, t), along_v[i]);
        tangents[i] = glm::vec4(t, handed < 0.0F ? -1.0F : 1.0F);
    }
    return tangents;
}

}  // namespace raster
