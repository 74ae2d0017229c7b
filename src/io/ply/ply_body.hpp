#pragma once

#include <raster/geometry/mesh.hpp>

#include "io/ply/ply_bytes.hpp"
#include "io/ply/ply_layout.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// What raster's PLY reader takes from a body: the vertices in raster's world and the faces'
// corners, read in one pass (doc/conventions.md#ply-reader).
namespace raster::detail {

struct PlyBody {
    // One per vertex kept: positions and normals mirrored in z as OBJ's are (doc/conventions.md#models),
    // normals zero and texture coordinates 0 where not finite, colours in linear light.
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;     // empty when the vertices have no nx, ny or nz
    std::vector<glm::vec2> uvs;         // empty without u, v (s, t, texture_u, ...)
    std::vector<LinearRgb> colours;     // empty without red, green, blue (or alpha)
    std::vector<float> alphas;          // empty without alpha; coverage in [0, 1] (doc/conventions.md#vertex-alpha)
    std::size_t unreadable_alphas = 0;  // alphas clamped into [0, 1]
    // Vertices whose position is not finite: skipped in a point cloud, kept as NaN (so faces
    // still count from 0) when the file has faces.
    std::size_t non_finite = 0;
    bool places_kept = false;  // whether those are kept, as NaN
    // Each face's corners, face f's from corners[face_starts[f]] to the next start.
    std::vector<std::uint32_t> corners;
    std::vector<std::uint64_t> face_starts;
    std::uint64_t declared_vertices = 0;
    std::string cut_short;  // "the PLY data is cut short: ..." when the data ends early, else ""
};

// Reads the body after the header, whose bytes `bytes` has already passed. Throws
// std::runtime_error naming `name` and the line (ASCII) or byte (binary) for what it cannot read.
[[nodiscard]] PlyBody read_ply_body(const PlyLayout& layout, PlyBytes& bytes, const std::string& name);

}  // namespace raster::detail
