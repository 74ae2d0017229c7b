// The arithmetic here is the scene reader's and meshes_by_material's for a mesh whose corners
// share nothing, step for step, so that every value is the one the assimp path gave.
#include "io/stl/stl_mesh.hpp"

#include "io/vertex_alpha.hpp"

#include <raster/image/colour.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace raster::detail {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The unit vector along v in float, or zero when v has no length or is not finite.
glm::vec3 unit_of(glm::dvec3 v) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::vec3(0.0F);
    return glm::vec3(v / length);
}

// A file position in raster's world: the node's identity matrix (which turns -0 into +0), then z mirrored.
glm::vec3 placed(glm::vec3 p) { return {p.x + 0.0F, p.y + 0.0F, -(p.z + 0.0F)}; }

// A colour channel as the scene reader takes an sRGB file's: clamped, then decoded to linear light.
float linear_channel(float written) {
    const float c = std::isfinite(written) ? std::clamp(written, 0.0F, 1.0F) : 1.0F;
    return static_cast<float>(linear_from_srgb_channel(c));
}

}  // namespace

StlMesh::StlMesh(double crease_degrees)
    : crease_degrees_(crease_degrees),
      cos_crease_(static_cast<float>(std::cos(crease_degrees * std::numbers::pi / 180.0))),
      normal_matrix_(glm::transpose(glm::inverse(glm::dmat3(glm::dmat4(1.0))))) {}

void StlMesh::reserve(std::size_t triangles) {
    mesh_.positions.reserve(triangles * 3);
    mesh_.normals.reserve(triangles * 3);
    mesh_.facets.reserve(triangles);
}

bool StlMesh::add(const std::array<glm::vec3, 3>& corners, glm::vec3 normal, const StlColour* colour) {
    if (!finite(corners[0]) || !finite(corners[1]) || !finite(corners[2])) return false;
    // Re-wound for raster's world: the file's first, third and second corners.
    const std::array<glm::vec3, 3> q{placed(corners[0]), placed(corners[2]), placed(corners[1])};
    const glm::dvec3 a = q[0], b = q[1], c = q[2];
    const glm::dvec3 weighted = glm::cross(b - a, c - b);
    const glm::vec3 unit = unit_of(weighted);
    if (unit == glm::vec3(0.0F)) return true;  // no area: it could never cover a pixel
    const glm::dvec3 turned = finite(normal) ? normal_matrix_ * glm::dvec3(normal) : glm::dvec3(0.0);
    glm::vec3 vertex_normal = unit_or_zero(glm::vec3(turned.x, turned.y, -turned.z));
    if (vertex_normal == glm::vec3(0.0F)) {  // the facet's own, smoothed over the one facet at each corner
        vertex_normal = unit;
        if (crease_degrees_ > 0.0 && glm::dot(unit, unit) >= cos_crease_) {
            glm::dvec3 sum(0.0);
            sum += glm::dvec3(unit) * glm::length(weighted);
            const glm::vec3 mean = unit_of(sum);
            if (mean != glm::vec3(0.0F)) vertex_normal = mean;
        }
    }
    const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
    for (const glm::vec3& p : q) {
        mesh_.positions.push_back(p);
        mesh_.normals.push_back(vertex_normal);
    }
    mesh_.facets.push_back({{first, first + 1, first + 2}, unit});
    if (colour != nullptr && !coloured_) start_colours();
    if (coloured_) {
        for (int k = 0; k < 3; ++k) push_colour(colour != nullptr ? *colour : default_colour_);
    }
    return true;
}

void StlMesh::start_colours() {
    coloured_ = true;
    const std::size_t before = mesh_.positions.size() - 3;
    mesh_.colours.reserve(mesh_.positions.capacity());
    mesh_.alphas.reserve(mesh_.positions.capacity());
    mesh_.colours.clear();
    mesh_.alphas.clear();
    for (std::size_t v = 0; v < before; ++v) push_colour(default_colour_);
}

void StlMesh::push_colour(const StlColour& colour) {
    mesh_.colours.push_back({linear_channel(colour.r), linear_channel(colour.g), linear_channel(colour.b)});
    std::size_t unreadable = 0;  // assimp's channels are bytes or 5 bits over their maximum: never outside [0, 1]
    const float alpha = vertex_alpha(colour.a, unreadable);
    translucent_ = translucent_ || alpha < 1.0F;
    mesh_.alphas.push_back(alpha);
}

void StlMesh::add_part_to(Model& model, const LinearRgb& diffuse) {
    if (mesh_.facets.empty()) return;
    if (!translucent_) mesh_.alphas = {};
    ModelPart part{"DefaultMaterial", std::move(mesh_), LinearMaterial{LinearRgb{}, diffuse, LinearRgb{}, {}}};
    settle_vertex_alphas(part, false);  // faces blend by their vertices' alpha, as another format's do
    model.parts.push_back(std::move(part));
}

}  // namespace raster::detail
