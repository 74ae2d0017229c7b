#pragma once

#include <raster/geometry/mesh.hpp>

#include <array>
#include <glm/vec3.hpp>

// Textured building blocks, raster-engine's shapes: every mesh carries texture coordinates in
// world units over `tile` (a texture repeats once per `tile` units), corners clockwise from
// outside, one normal per face.
namespace raster {

// A box of the given size centred on the origin, six faces of four corners each.
[[nodiscard]] Mesh textured_box(glm::vec3 size, float tile = 1.0F);
// A square pyramid: base `width` x `depth` centred on the origin at y = 0, apex at y = height.
[[nodiscard]] Mesh textured_pyramid(float width, float depth, float height, float tile = 1.0F);
// A horizontal rectangle at y = 0 facing +Y, centred on the origin.
[[nodiscard]] Mesh textured_ground(float width, float depth, float tile = 1.0F);
// A prism of `sides` equal sides round the Z axis (an octagon approximates a cylinder), from
// z = -length/2 to +length/2, its corners at `radius`; capped at both ends. u runs round it, v along.
[[nodiscard]] Mesh textured_prism(int sides, float radius, float length, float tile = 1.0F);
// One flat face through four corners in order round its edge (either way), facing away from
// `inside`; u along the first edge, v along the last, in world units over `tile`.
[[nodiscard]] Mesh textured_quad(const std::array<glm::vec3, 4>& corners, glm::vec3 inside, float tile = 1.0F);
// A (p, q) torus knot, a tube of `tube` radius about the curve
// ((2 + cos qt) cos pt, sin qt, (2 + cos qt) sin pt) / 2, with u along the knot (`repeats` times)
// and v round the tube; smooth normals.
[[nodiscard]] Mesh torus_knot(int p, int q, float tube, int segments, int sides, float repeats);

}  // namespace raster
