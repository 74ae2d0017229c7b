#include <raster/geometry/mesh.hpp>

#include "geometry/posing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster {

glm::vec3 facet_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) noexcept {
    // Clockwise from outside in a left-handed world: (b - a) x (c - b) points outward.
    return unit_or_zero(glm::cross(b - a, c - b));
}

Facet facet_facing_away(const std::vector<glm::vec3>& positions, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                        glm::vec3 inside) {
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
    detail::Posing posing(mesh, model, parts);
    posing.vertices(0, std::max(mesh.positions.size(), mesh.normals.size()));
    posing.facets(0, mesh.facets.size());
    return std::move(posing).take();
}

void append_posed(Mesh& whole, const Mesh& part, const glm::mat4& model) {
    const bool empty = whole.positions.empty();
    if (!empty && (whole.uvs.empty() != part.uvs.empty() || whole.colours.empty() != part.colours.empty() ||
                   whole.alphas.empty() != part.alphas.empty() || whole.tangents.empty() != part.tangents.empty() ||
                   whole.surface != part.surface)) {
        throw std::invalid_argument(
            "append_posed: the parts differ in texture coordinates, colours, alphas, tangents or surface");
    }
    Mesh moved = posed(part, model);
    const auto offset = static_cast<std::uint32_t>(whole.positions.size());
    for (Facet& facet : moved.facets) {
        for (std::uint32_t& corner : facet.corners) corner += offset;
    }
    whole.positions.insert(whole.positions.end(), moved.positions.begin(), moved.positions.end());
    whole.normals.insert(whole.normals.end(), moved.normals.begin(), moved.normals.end());
    whole.facets.insert(whole.facets.end(), moved.facets.begin(), moved.facets.end());
    whole.uvs.insert(whole.uvs.end(), moved.uvs.begin(), moved.uvs.end());
    whole.colours.insert(whole.colours.end(), moved.colours.begin(), moved.colours.end());
    whole.alphas.insert(whole.alphas.end(), moved.alphas.begin(), moved.alphas.end());
    whole.tangents.insert(whole.tangents.end(), moved.tangents.begin(), moved.tangents.end());
    whole.surface = part.surface;
    whole.convex = empty && part.convex;
}

namespace detail {

Posing::Posing(const Mesh& mesh, const glm::mat4& model, PoseParts parts)
    : source_(mesh), pose_(model),
      // A mirror turns clockwise into counter-clockwise: two corners are swapped to keep the convention.
      mirrored_(glm::determinant(glm::mat3(model)) < 0.0F), parts_(parts) {
    result_.surface = mesh.surface;
    result_.convex = mesh.convex;
    result_.positions.resize(mesh.positions.size());
    result_.normals.resize(mesh.normals.size());  // zero where vertex normals are left out
    result_.uvs = mesh.uvs;
    result_.colours = mesh.colours;
    result_.alphas = mesh.alphas;
    result_.tangents.resize(mesh.tangents.size());
    result_.facets.resize(mesh.facets.size());
}

void Posing::vertices(std::size_t begin, std::size_t end) noexcept {
    for (std::size_t i = begin; i < end; ++i) {  // normals may not match positions yet: drawing checks that
        if (i < source_.positions.size()) result_.positions[i] = pose_.position(source_.positions[i]);
        if (parts_.vertex_normals && i < source_.normals.size()) result_.normals[i] = pose_.normal(source_.normals[i]);
        if (i < source_.tangents.size()) result_.tangents[i] = pose_.tangent(source_.tangents[i], mirrored_);
    }
}

void Posing::facets(std::size_t begin, std::size_t end) noexcept {
    for (std::size_t f = begin; f < end; ++f) {
        Facet facet = source_.facets[f];
        if (mirrored_) std::swap(facet.corners[1], facet.corners[2]);
        facet.normal = parts_.facet_normals ? pose_.normal(facet.normal) : glm::vec3(0.0F);
        result_.facets[f] = facet;
    }
}

}  // namespace detail

}  // namespace raster
