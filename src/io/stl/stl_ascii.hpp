#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/ply/ply_bytes.hpp"

#include <string>

// An ASCII STL: solid ... facet normal x y z, outer loop, three vertex x y z, endloop, endfacet,
// ... endsolid, one or more solids, read word by word in one pass (doc/conventions.md#stl-reader).
namespace raster::detail {

// The model in `bytes`, positioned at the file's start; throws std::runtime_error naming `name`
// and the line for words out of place, numbers that are not numbers, corners that are not finite
// points and a file that ends inside a facet.
[[nodiscard]] Model read_ascii_stl(PlyBytes& bytes, const std::string& name, const ObjOptions& options, Model model);

}  // namespace raster::detail
