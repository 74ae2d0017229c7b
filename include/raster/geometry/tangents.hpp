#pragma once

#include <raster/geometry/mesh.hpp>

#include <vector>
#include <glm/vec4.hpp>

// Per-vertex tangents for normal maps, made the MikkTSpace way from the texture coordinates
// (doc/conventions.md#normal-maps).
namespace raster {

// One tangent per position: xyz the unit direction in which u grows, in the plane of the
// vertex's normal, and w = ±1 such that w · (normal × tangent) is the direction in which v
// grows. Each facet's u and v directions are summed into its corners weighted by the corner's
// angle, then made perpendicular to the normal; where the texture coordinates give no direction
// (none, all equal, or along a line) the tangent is any unit vector perpendicular to the normal
// and w is 1. Empty when the mesh has no texture coordinates; never NaN.
[[nodiscard]] std::vector<glm::vec4> tangents_from_uvs(const Mesh& mesh);

}  // namespace raster
