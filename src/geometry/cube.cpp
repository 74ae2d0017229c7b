#include <raster/geometry/cube.hpp>

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster {
namespace {

// Corner i has x = +0.5 when bit 0 is set, y when bit 1 is, z when bit 2 is.
std::array<glm::vec3, 8> unit_corners() {
    std::array<glm::vec3, 8> corners{};
    for (std::size_t i = 0; i < corners.size(); ++i) {
        corners[i] = {(i & 1U) ? 0.5F : -0.5F, (i & 2U) ? 0.5F : -0.5F, (i & 4U) ? 0.5F : -0.5F};
    }
    return corners;
}

}  // namespace

Cube::Cube()
    : corners_(unit_corners()), faces_{{
                                    {{0, 2, 3, 1}, {0.0F, 0.0F, -1.0F}},  // near (-Z)
                                    {{5, 7, 6, 4}, {0.0F, 0.0F, 1.0F}},   // far (+Z)
                                    {{1, 3, 7, 5}, {1.0F, 0.0F, 0.0F}},   // right (+X)
                                    {{4, 6, 2, 0}, {-1.0F, 0.0F, 0.0F}},  // left (-X)
                                    {{2, 6, 7, 3}, {0.0F, 1.0F, 0.0F}},   // top (+Y)
                                    {{1, 5, 4, 0}, {0.0F, -1.0F, 0.0F}},  // bottom (-Y)
                                }} {}

Cube Cube::posed(const glm::mat4& model) const {
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
    Cube result = *this;
    for (glm::vec3& corner : result.corners_) corner = glm::vec3(model * glm::vec4(corner, 1.0F));
    for (Face& face : result.faces_) face.normal = glm::normalize(normal_matrix * face.normal);
    return result;
}

std::vector<Edge> Cube::edges() const {
    constexpr std::array<std::size_t, 6> kAllSlots{0, 1, 2, 3, 4, 5};
    return edges_of(kAllSlots);
}

std::vector<Edge> Cube::edges_of(std::span<const std::size_t> slots) const {
    std::vector<Edge> edges;
    for (const std::size_t slot : slots) {
        const Face& face = faces_.at(slot);
        for (std::size_t i = 0; i < face.corners.size(); ++i) {
            const std::size_t a = face.corners[i];
            const std::size_t b = face.corners[(i + 1) % face.corners.size()];
            const Edge edge{std::min(a, b), std::max(a, b)};
            if (std::find(edges.begin(), edges.end(), edge) == edges.end()) edges.push_back(edge);
        }
    }
    return edges;
}

}  // namespace raster
