#include <raster/geometry/primitives.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>
#include <glm/geometric.hpp>

namespace raster {

namespace {

// A flat four-cornered face; corners in order round its edge, either way.
void add_face(Mesh& mesh, const std::array<glm::vec3, 4>& corners, const std::array<glm::vec2, 4>& uvs,
              glm::vec3 inside) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    const glm::vec3 normal = unit_or_zero(glm::cross(corners[1] - corners[0], corners[2] - corners[1]));
    for (std::size_t k = 0; k < 4; ++k) {
        mesh.positions.push_back(corners[k]);
        mesh.uvs.push_back(uvs[k]);
        mesh.normals.push_back(normal);
    }
    mesh.facets.push_back(facet_facing_away(mesh.positions, first, first + 1, first + 2, inside));
    mesh.facets.push_back(facet_facing_away(mesh.positions, first, first + 2, first + 3, inside));
    for (std::uint32_t k = first; k < first + 4; ++k) {
        mesh.normals[k] = mesh.facets.back().normal;  // the outward one, whichever way the corners ran
    }
}

}  // namespace

Mesh textured_box(glm::vec3 size, float tile) {
    Mesh mesh;
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    const glm::vec3 h = size * 0.5F;
    // Each face: its two in-plane axes as (axis, extent) pairs; u along the first, v along the second.
    for (int axis = 0; axis < 3; ++axis) {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        for (const float side : {-1.0F, 1.0F}) {
            std::array<glm::vec3, 4> corners{};
            std::array<glm::vec2, 4> uvs{};
            const std::array<std::array<float, 2>, 4> signs{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
            for (std::size_t k = 0; k < 4; ++k) {
                glm::vec3 p(0.0F);
                p[axis] = side * h[axis];
                p[a] = signs[k][0] * h[a];
                p[b] = signs[k][1] * h[b];
                corners[k] = p;
                // Vertical faces keep v up the wall; horizontal ones use x and z.
                const float u = axis == 1 ? p.x : (axis == 0 ? p.z : p.x);
                const float v = axis == 1 ? p.z : p.y;
                uvs[k] = glm::vec2(u, v) / tile;
            }
            add_face(mesh, corners, uvs, glm::vec3(0.0F));
        }
    }
    return mesh;
}

Mesh textured_pyramid(float width, float depth, float height, float tile) {
    Mesh mesh;
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    const float x = width * 0.5F, z = depth * 0.5F;
    const glm::vec3 apex(0.0F, height, 0.0F), inside(0.0F, height * 0.25F, 0.0F);
    const std::array<glm::vec3, 4> base{{{-x, 0, -z}, {x, 0, -z}, {x, 0, z}, {-x, 0, z}}};
    for (std::size_t k = 0; k < 4; ++k) {
        const glm::vec3 a = base[k], b = base[(k + 1) % 4];
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        const float run = glm::length(b - a), slant = glm::length(apex - (a + b) * 0.5F);
        mesh.positions.insert(mesh.positions.end(), {a, b, apex});
        mesh.uvs.insert(mesh.uvs.end(),
                        {glm::vec2(0.0F), glm::vec2(run / tile, 0.0F), glm::vec2(run * 0.5F / tile, slant / tile)});
        mesh.facets.push_back(facet_facing_away(mesh.positions, first, first + 1, first + 2, inside));
        mesh.normals.insert(mesh.normals.end(), 3, mesh.facets.back().normal);
    }
    add_face(mesh, base,
             {glm::vec2(-x, -z) / tile, glm::vec2(x, -z) / tile, glm::vec2(x, z) / tile, glm::vec2(-x, z) / tile},
             inside);
    return mesh;
}

Mesh textured_ground(float width, float depth, float tile) {
    Mesh mesh;
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    const float x = width * 0.5F, z = depth * 0.5F;
    add_face(mesh, {glm::vec3(-x, 0, -z), glm::vec3(x, 0, -z), glm::vec3(x, 0, z), glm::vec3(-x, 0, z)},
             {glm::vec2(-x, -z) / tile, glm::vec2(x, -z) / tile, glm::vec2(x, z) / tile, glm::vec2(-x, z) / tile},
             glm::vec3(0, -1, 0));
    return mesh;
}

Mesh textured_prism(int sides, float radius, float length, float tile) {
    Mesh mesh;
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    const float z = length * 0.5F;
    const double step = 2.0 * std::numbers::pi / sides;
    const float side = 2.0F * radius * static_cast<float>(std::sin(step / 2.0));
    std::vector<glm::vec3> ring;
    for (int k = 0; k < sides; ++k) {
        ring.emplace_back(radius * static_cast<float>(std::cos(k * step)),
                          radius * static_cast<float>(std::sin(k * step)), 0.0F);
    }
    for (int k = 0; k < sides; ++k) {
        const glm::vec3 a = ring[static_cast<std::size_t>(k)], b = ring[static_cast<std::size_t>((k + 1) % sides)];
        const float u0 = static_cast<float>(k) * side / tile, u1 = u0 + side / tile;
        add_face(mesh,
                 {a + glm::vec3(0, 0, -z), b + glm::vec3(0, 0, -z), b + glm::vec3(0, 0, z), a + glm::vec3(0, 0, z)},
                 {glm::vec2(u0, -z / tile), glm::vec2(u1, -z / tile), glm::vec2(u1, z / tile), glm::vec2(u0, z / tile)},
                 glm::vec3(0.0F));
    }
    // Each cap a fan of triangles round its centre, so that any number of sides stays flat and convex.
    for (const float end : {-z, z}) {
        const glm::vec3 centre(0.0F, 0.0F, end), inside(0.0F, 0.0F, -end);
        for (int k = 0; k < sides; ++k) {
            const auto first = static_cast<std::uint32_t>(mesh.positions.size());
            const glm::vec3 a = ring[static_cast<std::size_t>(k)] + centre,
                            b = ring[static_cast<std::size_t>((k + 1) % sides)] + centre;
            mesh.positions.insert(mesh.positions.end(), {centre, a, b});
            mesh.uvs.insert(mesh.uvs.end(), {glm::vec2(0.0F), glm::vec2(a.x, a.y) / tile, glm::vec2(b.x, b.y) / tile});
            mesh.facets.push_back(facet_facing_away(mesh.positions, first, first + 1, first + 2, inside));
            mesh.normals.insert(mesh.normals.end(), 3, mesh.facets.back().normal);
        }
    }
    return mesh;
}

Mesh textured_quad(const std::array<glm::vec3, 4>& corners, glm::vec3 inside, float tile) {
    Mesh mesh;
    mesh.surface = Surface::faceted;
    mesh.convex = true;
    const glm::vec3 along = unit_or_zero(corners[1] - corners[0]);
    const glm::vec3 across = unit_or_zero(corners[3] - corners[0] - along * glm::dot(corners[3] - corners[0], along));
    std::array<glm::vec2, 4> uvs{};
    for (std::size_t k = 0; k < 4; ++k) {
        const glm::vec3 d = corners[k] - corners[0];
        uvs[k] = glm::vec2(glm::dot(d, along), glm::dot(d, across)) / tile;
    }
    add_face(mesh, corners, uvs, inside);
    return mesh;
}

Mesh torus_knot(int p, int q, float tube, int segments, int sides, float repeats) {
    const auto curve = [&](double t) {
        const double r = 2.0 + std::cos(q * t);
        return glm::dvec3(r * std::cos(p * t), std::sin(q * t), r * std::sin(p * t)) / 2.0;
    };
    Mesh mesh;
    const double tau = 2.0 * std::numbers::pi;
    for (int i = 0; i <= segments; ++i) {
        const double t = tau * i / segments, dt = 1e-4;
        const glm::dvec3 centre = curve(t);
        const glm::dvec3 tangent = glm::normalize(curve(t + dt) - curve(t - dt));
        const glm::dvec3 bend = curve(t + dt) + curve(t - dt) - 2.0 * centre;
        const glm::dvec3 binormal = glm::normalize(glm::cross(tangent, bend));
        const glm::dvec3 normal = glm::cross(binormal, tangent);
        for (int j = 0; j <= sides; ++j) {
            const double a = tau * j / sides;
            const glm::dvec3 out = std::cos(a) * normal + std::sin(a) * binormal;
            mesh.positions.emplace_back(centre + static_cast<double>(tube) * out);
            mesh.normals.emplace_back(out);
            mesh.uvs.emplace_back(repeats * static_cast<float>(i) / static_cast<float>(segments),
                                  static_cast<float>(j) / static_cast<float>(sides));
        }
    }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (sides + 1) + j); };
    for (int i = 0; i < segments; ++i) {
        for (int j = 0; j < sides; ++j) {
            const glm::vec3 inside = mesh.positions[at(i, j)] - mesh.normals[at(i, j)] * tube;
            mesh.facets.push_back(facet_facing_away(mesh.positions, at(i, j), at(i + 1, j), at(i + 1, j + 1), inside));
            mesh.facets.push_back(facet_facing_away(mesh.positions, at(i, j), at(i + 1, j + 1), at(i, j + 1), inside));
        }
    }
    return mesh;
}

}  // namespace raster
