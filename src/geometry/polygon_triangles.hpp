#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec3.hpp>

// Triangles of a model file's polygon faces, which may be concave or touch themselves along a slit.
namespace raster::detail {

// Splits a face of n >= 3 corners (in file order, any winding, convex or not, planar or nearly so)
// into exactly n - 2 triangles that cover exactly its own area: ear clipping in the plane of the face,
// except that a quad convex in that plane is cut along its shorter diagonal. Each triangle lists
// indices into `corners`, in the face's own winding order.
[[nodiscard]] std::vector<std::array<std::uint32_t, 3>> triangles_of_polygon(std::span<const glm::dvec3> corners);

}  // namespace raster::detail
