#include <raster/geometry/shapes.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <glm/geometric.hpp>

namespace raster {
namespace {

constexpr glm::vec3 kCentre{0.0F, 0.0F, 0.0F};

std::uint32_t index_of(std::size_t i) { return static_cast<std::uint32_t>(i); }

// Gives every vertex of a faceted mesh a normal (unused by its shading) so the arrays match.
void add_placeholder_normals(Mesh& mesh) { mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0F)); }

}  // namespace

Mesh cube_mesh() {
    Mesh mesh;
    // Corner i has x = +0.5 when bit 0 is set, y when bit 1 is, z when bit 2 is.
    for (std::size_t i = 0; i < 8; ++i) {
        mesh.positions.push_back({(i & 1U) ? 0.5F : -0.5F, (i & 2U) ? 0.5F : -0.5F, (i & 4U) ? 0.5F : -0.5F});
    }
    // The quads of Cube, each split along its first diagonal.
    constexpr std::uint32_t kQuads[6][4] = {{0, 2, 3, 1}, {5, 7, 6, 4}, {1, 3, 7, 5},
                                            {4, 6, 2, 0}, {2, 6, 7, 3}, {1, 5, 4, 0}};
    for (const auto& quad : kQuads) {
        mesh.facets.push_back(facet_facing_away(mesh.positions, quad[0], quad[1], quad[2], kCentre));
        mesh.facets.push_back(facet_facing_away(mesh.positions, quad[0], quad[2], quad[3], kCentre));
    }
    add_placeholder_normals(mesh);
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    return mesh;
}

Mesh dodecahedron() {
    const float phi = std::numbers::phi_v<float>;
    const float inverse = 1.0F / phi;
    Mesh mesh;
    for (const float x : {-1.0F, 1.0F}) {
        for (const float y : {-1.0F, 1.0F}) {
            for (const float z : {-1.0F, 1.0F}) mesh.positions.push_back({x, y, z});
        }
    }
    for (const float a : {-1.0F, 1.0F}) {
        for (const float b : {-1.0F, 1.0F}) {
            mesh.positions.push_back({0.0F, a * inverse, b * phi});
            mesh.positions.push_back({a * inverse, b * phi, 0.0F});
            mesh.positions.push_back({a * phi, 0.0F, b * inverse});
        }
    }
    for (glm::vec3& p : mesh.positions) p *= 0.5F / phi;
    // Each pentagon faces one corner direction of the dual icosahedron, (0, +-phi, +-1) and the
    // cyclic shifts of (0, phi, 1); its corners are the five vertices farthest along it.
    for (const float a : {-1.0F, 1.0F}) {
        for (const float b : {-1.0F, 1.0F}) {
            for (const glm::vec3 axis :
                 {glm::vec3(0.0F, a * phi, b), glm::vec3(a * phi, b, 0.0F), glm::vec3(b, 0.0F, a * phi)}) {
                std::vector<std::uint32_t> corners(mesh.positions.size());
                for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = index_of(i);
                std::partial_sort(corners.begin(), corners.begin() + 5, corners.end(), [&](auto i, auto j) {
                    return glm::dot(mesh.positions[i], axis) > glm::dot(mesh.positions[j], axis);
                });
                corners.resize(5);
                // Order the five by angle around the axis, then fan from the first.
                const glm::vec3 u =
                    glm::normalize(mesh.positions[corners[0]] -
                                   axis * glm::dot(mesh.positions[corners[0]], axis) / glm::dot(axis, axis));
                const glm::vec3 v = glm::normalize(glm::cross(axis, u));
                std::sort(corners.begin(), corners.end(), [&](auto i, auto j) {
                    return std::atan2(glm::dot(mesh.positions[i], v), glm::dot(mesh.positions[i], u)) <
                           std::atan2(glm::dot(mesh.positions[j], v), glm::dot(mesh.positions[j], u));
                });
                for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
                    mesh.facets.push_back(
                        facet_facing_away(mesh.positions, corners[0], corners[k], corners[k + 1], kCentre));
                }
            }
        }
    }
    add_placeholder_normals(mesh);
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    return mesh;
}

Mesh sphere(int level) {
    if (level < 0 || level > kMaxSphereLevel) {
        throw std::invalid_argument("sphere level must be 0.." + std::to_string(kMaxSphereLevel) + ", got " +
                                    std::to_string(level));
    }
    Mesh mesh;
    mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const std::uint32_t x : {0U, 1U}) {
        for (const std::uint32_t y : {2U, 3U}) {
            for (const std::uint32_t z : {4U, 5U})
                triangles.push_back(facet_facing_away(mesh.positions, x, y, z, kCentre).corners);
        }
    }
    for (int pass = 0; pass < level; ++pass) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto [found, added] = midpoints.try_emplace(key, index_of(mesh.positions.size()));
            if (added) mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
            return found->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        finer.reserve(triangles.size() * 4);
        for (const auto& [a, b, c] : triangles) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({ab, b, bc});
            finer.push_back({ca, bc, c});
            finer.push_back({ab, bc, ca});
        }
        triangles = std::move(finer);
    }
    mesh.facets.reserve(triangles.size());
    for (const auto& [a, b, c] : triangles) {
        mesh.facets.push_back({{a, b, c}, facet_normal(mesh.positions[a], mesh.positions[b], mesh.positions[c])});
    }
    mesh.normals = mesh.positions;
    mesh.convex = true;
    return mesh;
}

Mesh torus(int ring, int tube) {
    if (ring < 3 || tube < 3 || std::int64_t{ring} * tube > kMaxTorusVertices) {
        throw std::invalid_argument("torus needs ring and tube segments of at least 3 with ring * tube at most " +
                                    std::to_string(kMaxTorusVertices) + ", got " + std::to_string(ring) + " x " +
                                    std::to_string(tube));
    }
    Mesh mesh;
    const auto count = static_cast<std::size_t>(ring) * static_cast<std::size_t>(tube);
    mesh.positions.reserve(count);
    mesh.normals.reserve(count);
    for (int i = 0; i < ring; ++i) {
        const double u = 2.0 * std::numbers::pi * i / ring;
        for (int j = 0; j < tube; ++j) {
            const double v = 2.0 * std::numbers::pi * j / tube;
            const double radius = kTorusRingRadius + kTorusTubeRadius * std::cos(v);
            mesh.positions.emplace_back(radius * std::cos(u), kTorusTubeRadius * std::sin(v), radius * std::sin(u));
            mesh.normals.emplace_back(std::cos(u) * std::cos(v), std::sin(v), std::sin(u) * std::cos(v));
        }
    }
    const auto at = [&](int i, int j) { return index_of(static_cast<std::size_t>((i % ring) * tube + j % tube)); };
    mesh.facets.reserve(2 * count);
    for (int i = 0; i < ring; ++i) {
        for (int j = 0; j < tube; ++j) {
            const std::uint32_t i0 = at(i, j), i1 = at(i + 1, j), i2 = at(i + 1, j + 1), i3 = at(i, j + 1);
            for (const std::array<std::uint32_t, 3> corners : {std::array{i0, i1, i2}, std::array{i0, i2, i3}}) {
                // The tube's centre line is inside: turn each facet's normal away from it.
                const glm::vec3 p = mesh.positions[corners[0]];
                const glm::vec3 axis = kTorusRingRadius * glm::normalize(glm::vec3(p.x, 0.0F, p.z));
                mesh.facets.push_back(facet_facing_away(mesh.positions, corners[0], corners[1], corners[2], axis));
            }
        }
    }
    return mesh;
}

Mesh ground_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    Mesh mesh;
    mesh.positions = {a, b, c, d};
    const glm::vec3 below = (a + b + c + d) / 4.0F - glm::vec3(0.0F, 1.0F, 0.0F);
    mesh.facets.push_back(facet_facing_away(mesh.positions, 0, 1, 2, below));
    mesh.facets.push_back(facet_facing_away(mesh.positions, 0, 2, 3, below));
    mesh.normals.assign(4, glm::vec3(0.0F, 1.0F, 0.0F));
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    return mesh;
}

}  // namespace raster
