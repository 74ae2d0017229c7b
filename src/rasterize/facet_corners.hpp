#pragma once

#include <raster/geometry/mesh.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/image/subpixel.hpp>
#include <raster/rasterize/depth_buffer.hpp>
#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/shader.hpp>

#include "rasterize/triangle_loop.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

// The vertex stage shared by both front ends: a mesh checked before it is drawn, and the
// Varying of each facet's corners.
namespace raster::detail {

// Throws std::invalid_argument for a depth buffer of another size or a mesh whose facets or
// normals do not match its vertices.
inline void check_drawable(const Framebuffer& colour, const DepthBuffer* depth_buffer, const Mesh& mesh) {
    if (depth_buffer != nullptr &&
        (depth_buffer->width() != colour.width() || depth_buffer->height() != colour.height())) {
        throw std::invalid_argument("depth buffer and framebuffer differ in size");
    }
    if (mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.uvs.size()) + " texture coordinates for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    if (!mesh.colours.empty() && mesh.colours.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.colours.size()) + " colours for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    if (!mesh.alphas.empty() && mesh.alphas.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.alphas.size()) + " alphas for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    if (!mesh.tangents.empty() && mesh.tangents.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.tangents.size()) + " tangents for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    for (const Facet& facet : mesh.facets) {
        for (const std::uint32_t corner : facet.corners) {
            if (corner >= mesh.positions.size()) throw std::invalid_argument("mesh facet names a missing vertex");
        }
    }
}

// What the vertex stage sees of corner k of a facet, at `position` with `normal`.
inline Corner corner_of(const Mesh& mesh, const Facet& facet, std::size_t k, glm::vec3 position, glm::vec3 normal) {
    const std::uint32_t i = facet.corners[k];
    return {position,
            normal,
            mesh.uvs.empty() ? glm::vec2(0.0F) : mesh.uvs[i],
            mesh.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : mesh.colours[i],
            mesh.tangents.empty() ? glm::vec4(0.0F) : mesh.tangents[i],
            mesh.alphas.empty() ? 1.0F : mesh.alphas[i]};
}

// The Varying of each corner of a facet, from the vertex stage's per-vertex results or, for
// facet normals, made here.
template <typename Shader>
std::array<typename Shader::Varying, 3> facet_varyings(const Shader& shader, const Mesh& mesh, const Facet& facet,
                                                       const std::vector<typename Shader::Varying>& per_vertex) {
    const std::array<glm::vec3, 3> at{mesh.positions[facet.corners[0]], mesh.positions[facet.corners[1]],
                                      mesh.positions[facet.corners[2]]};
    if (Shader::kFacetNormal) {  // lit once per facet at its centroid; texture coordinates and colours stay each
                                 // corner's own
        const glm::vec3 centroid = at[0] / 3.0F + at[1] / 3.0F + at[2] / 3.0F;  // no overflow
        if (mesh.uvs.empty() && mesh.colours.empty() && mesh.alphas.empty()) {
            const auto shared = shader.vertex({centroid, facet.normal});
            return {shared, shared, shared};
        }
        return {shader.vertex(corner_of(mesh, facet, 0, centroid, facet.normal)),
                shader.vertex(corner_of(mesh, facet, 1, centroid, facet.normal)),
                shader.vertex(corner_of(mesh, facet, 2, centroid, facet.normal))};
    }
    if (mesh.surface == Surface::faceted) {  // the facet's normal, each corner's own position
        return {shader.vertex(corner_of(mesh, facet, 0, at[0], facet.normal)),
                shader.vertex(corner_of(mesh, facet, 1, at[1], facet.normal)),
                shader.vertex(corner_of(mesh, facet, 2, at[2], facet.normal))};
    }
    return {per_vertex[facet.corners[0]], per_vertex[facet.corners[1]], per_vertex[facet.corners[2]]};
}

// The vertex stage's Varying of vertex i, for shaders that light per vertex or per pixel.
template <typename Shader>
typename Shader::Varying vertex_varying(const Shader& shader, const Mesh& mesh, std::size_t i) {
    return shader.vertex({mesh.positions[i], mesh.normals[i], mesh.uvs.empty() ? glm::vec2(0.0F) : mesh.uvs[i],
                          mesh.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : mesh.colours[i],
                          mesh.tangents.empty() ? glm::vec4(0.0F) : mesh.tangents[i],
                          mesh.alphas.empty() ? 1.0F : mesh.alphas[i]});
}

// Whether a triangle's corners leave every pixel centre of a band of rows above or below them,
// so that drawing into that band can skip it before any shading work.
inline bool misses_rows(const std::array<SubpixelPoint, 3>& points, const PixelRect& rows) noexcept {
    const std::int32_t low = std::min({points[0].y, points[1].y, points[2].y});
    const std::int32_t high = std::max({points[0].y, points[1].y, points[2].y});
    return high < rows.y * kSubpixelOne || low > (rows.y + rows.height - 1) * kSubpixelOne;
}

// A snapped facet handed to `visit` with its corners' Varyings when it faces the camera
// (positive snapped area, the numbers the fill uses); whether it did.
template <typename Shader, typename Visit>
bool visit_if_facing(std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, const Shader& shader,
                     const Mesh& mesh, const Facet& facet, const std::vector<typename Shader::Varying>& per_vertex,
                     Visit& visit) {
    const std::array<SubpixelPoint, 3> points{corners[0].at, corners[1].at, corners[2].at};
    if (twice_signed_area(points) <= 0) return false;  // facing away, or seen edge-on
    const std::array<typename Shader::Varying, 3> values = facet_varyings(shader, mesh, facet, per_vertex);
    for (std::size_t k = 0; k < 3; ++k) corners[k].varying = values[k];
    visit(corners);
    return true;
}

}  // namespace raster::detail
