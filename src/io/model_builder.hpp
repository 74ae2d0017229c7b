#pragma once

#include <raster/geometry/mesh.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// Indexed meshes from a model file's triangles, whose corners index positions, normals,
// texture coordinates, colours and tangents separately (as OBJ does), with normals made where the file has none.
namespace raster::detail {

// Indices are 32 bits, as a Mesh's are: readers refuse a file of more vertices (kMaxSoupVertices).
inline constexpr std::uint32_t kNoIndex = 0xFFFFFFFFU;
inline constexpr std::size_t kMaxSoupVertices = kNoIndex;

struct SoupCorner {
    std::uint32_t position;
    std::uint32_t normal = kNoIndex;
    std::uint32_t uv = kNoIndex;
    std::uint32_t colour = kNoIndex;
    std::uint32_t tangent = kNoIndex;  // into PolygonSoup::tangents, in raster's world (doc/conventions.md#normal-maps)
};

// Corners clockwise seen from outside, in raster's world; every index valid or kNoIndex.
struct SoupTriangle {
    std::array<SoupCorner, 3> corners;
    int material;
};

// A vertex drawn as a splat, and two drawn as a line (doc/conventions.md#points-and-lines).
struct SoupPoint {
    SoupCorner corner;
    int material;
};
struct SoupSegment {
    std::array<SoupCorner, 2> ends;
    int material;
};

struct PolygonSoup {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<LinearRgb> colours;  // in linear light
    // Empty, or each colour's alpha in [0, 1] by the same index (SoupCorner::colour); one missing reads as 1.
    std::vector<float> alphas{};
    std::vector<glm::vec4> tangents{};
    std::vector<SoupTriangle> triangles;
    std::vector<SoupPoint> points{};
    std::vector<SoupSegment> segments{};
};

// Every vertex with finite coordinates as a point of the default material, the n-th normal
// its normal when there are as many normals as vertices, its colour when there are colours.
void add_every_vertex_as_a_point(PolygonSoup& soup);

// One mesh per material the triangles use, in order of material; a mesh whose vertex alphas are all 1 keeps none. Each
// corner without a usable normal takes the area-weighted mean of the facet normals around its position that lie within
// `crease_degrees` of its own facet's (0: every facet flat). Triangles with no area are dropped.
// Points and segments keep the file's normal, or none (zero): they are drawn in their colour.
// The normals are worked out on up to `threads` threads; the meshes are the same for any count.
[[nodiscard]] std::vector<std::pair<int, Mesh>> meshes_by_material(const PolygonSoup& soup, double crease_degrees,
                                                                   std::size_t threads = 1);

}  // namespace raster::detail
