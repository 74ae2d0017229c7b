#pragma once

#include "io/ply/ply_layout.hpp"

#include <string>
#include <vector>

// What a PLY carries that raster does not draw, named rather than dropped in silence
// (doc/conventions.md#ply-reader).
namespace raster::detail {

// One warning naming `name` for each of: the vertex properties not drawn, the face properties not
// drawn, the elements not drawn (those of no items or properties left out). `for_assimp`: the file goes to
// assimp's reader, which also reads material and triangle-strip elements and faces' texture
// coordinates and material indices.
[[nodiscard]] std::vector<std::string> ply_unread_warnings(const PlyLayout& layout, const std::string& name,
                                                           bool for_assimp);

}  // namespace raster::detail
