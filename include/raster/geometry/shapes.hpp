#pragma once

#include <raster/geometry/mesh.hpp>

namespace raster {

// The analytic shapes behind the diary's smooth meshes (the unit sphere, the 0.7 / 0.3 torus).
enum class ShapeKind { sphere, torus };

// The diary's shapes, each centred on the origin with facets clockwise from outside.

// The cube of edge 1 as 8 shared corners and 12 facets, two per side; faceted and convex.
[[nodiscard]] Mesh cube_mesh();

// The regular dodecahedron with corners at most 0.5 from the origin in any coordinate (edge
// 1/phi^2): 20 corners, each pentagon a fan of 3 facets, 36 in all; faceted and convex.
[[nodiscard]] Mesh dodecahedron();

// The deepest sphere subdivision: level 8 has 524,288 facets (about 25 MB).
inline constexpr int kMaxSphereLevel = 8;
// The unit sphere from an octahedron split `level` times, every facet into four, with edge
// midpoints shared and pushed onto the sphere: 8 * 4^level facets, 4^(level+1) + 2 vertices.
// Normals are the positions; convex. Throws std::invalid_argument outside 0..kMaxSphereLevel.
[[nodiscard]] Mesh sphere(int level);

// The most vertices a torus may have, ring * tube: 2^20 (2,097,152 facets, about 100 MB).
inline constexpr int kMaxTorusVertices = 1 << 20;
inline constexpr float kTorusRingRadius = 0.7F;
inline constexpr float kTorusTubeRadius = 0.3F;
// The torus with the ring of radius 0.7 in the XZ plane and a tube of radius 0.3, sampled at
// `ring` angles around Y and `tube` angles around the tube: ring * tube vertices, twice as many
// facets. Throws std::invalid_argument unless both are at least 3 and the product is at most
// kMaxTorusVertices.
[[nodiscard]] Mesh torus(int ring, int tube);

// A flat quadrilateral of two facets facing +Y (its normal), corners in order around it.
[[nodiscard]] Mesh ground_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

}  // namespace raster
