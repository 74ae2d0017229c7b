#pragma once

#include <raster/image/colour.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace raster {

// Three corners, clockwise seen from outside (doc/conventions.md#winding), and the outward
// unit normal of the plane through them.
struct Facet {
    std::array<std::uint32_t, 3> corners;
    glm::vec3 normal;
};

// How a mesh's corners take their normals: a smooth surface uses the per-vertex normals, a
// faceted one (a cube, a dodecahedron) gives every corner its facet's normal.
enum class Surface { smooth, faceted };

// An indexed triangle mesh: shared vertex positions with one normal each (and one texture
// coordinate and one colour each, or none at all), and facets.
struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<Facet> facets;
    Surface surface = Surface::smooth;
    // No facet can hide another when back faces are culled, so it needs no depth buffer
    // (doc/conventions.md#depth).
    bool convex = false;
    std::vector<glm::vec2> uvs{};  // empty, or one per position (doc/conventions.md#textures)
    // Empty, or one per position, multiplying a linear material's diffuse colour
    // (doc/conventions.md#vertex-colours).
    std::vector<LinearRgb> colours{};
    // Empty, or one per position: the coverage in [0, 1] multiplying the material's alpha where it
    // blends or masks, as glTF's COLOR_0 alpha does; empty when every vertex is opaque
    // (doc/conventions.md#vertex-alpha).
    std::vector<float> alphas{};
    // Vertices drawn as round splats and pairs drawn as lines, beside the facets and over the
    // same vertex arrays (doc/conventions.md#points-and-lines); empty for a surface alone.
    std::vector<std::uint32_t> points{};
    std::vector<std::array<std::uint32_t, 2>> segments{};
    // Empty, or one per position for a normal map: xyz the direction u grows in, w = ±1 with
    // w (normal × tangent) the direction v grows in (doc/conventions.md#normal-maps).
    std::vector<glm::vec4> tangents{};
};

// The unit vector along v, or zero when v has no usable direction (zero, NaN, infinite).
// Inline: Phong shading renormalises at every pixel.
[[nodiscard]] inline glm::vec3 unit_or_zero(glm::vec3 v) noexcept {
    const float squared = glm::dot(v, v);
    if (!(squared > 0.0F) || !(squared < std::numeric_limits<float>::infinity())) return glm::vec3(0.0F);
    return v / std::sqrt(squared);
}

// The unit normal of a facet whose corners run clockwise seen from outside; zero when the
// corners are collinear, coincide or are not finite.
[[nodiscard]] glm::vec3 facet_normal(glm::vec3 a, glm::vec3 b, glm::vec3 c) noexcept;

// A facet through corners a, b, c, turned if need be so that its normal points away from
// `inside`; how shapes built around a centre get their winding right.
[[nodiscard]] Facet facet_facing_away(const std::vector<glm::vec3>& positions, std::uint32_t a, std::uint32_t b,
                                      std::uint32_t c, glm::vec3 inside);

// The mesh moved by `model`: positions as points, normals by the inverse transpose of the
// linear part and renormalised, so non-uniform scale keeps them perpendicular to the surface;
// tangents as directions by the linear part. A mirroring model (negative determinant) keeps
// facets clockwise from outside and turns each tangent's w round.
[[nodiscard]] Mesh posed(const Mesh& mesh, const glm::mat4& model);

// Which normals posed() moves: a shader lit per facet never reads the vertex normals, a smooth
// one never the facet normals, and a render skips the one it does not need (left zero).
struct PoseParts {
    bool vertex_normals = true;
    bool facet_normals = true;
};
[[nodiscard]] Mesh posed(const Mesh& mesh, const glm::mat4& model, PoseParts parts);

// Adds `part`, moved by `model` (as posed() moves it), to `whole`: many parts that share a
// surface become one mesh, drawn in one call. The result is convex only if both were empty or it.
void append_posed(Mesh& whole, const Mesh& part, const glm::mat4& model);

}  // namespace raster
