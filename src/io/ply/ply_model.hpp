#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/ply/ply_body.hpp"

#include <string>

// A PLY's vertices and faces as the parts of a Model (doc/conventions.md#ply-reader).
namespace raster::detail {

// Appends `body`'s parts to `model` with its warnings; throws std::runtime_error naming `name`
// for a body with nothing to draw or a face on a vertex that is not a finite point.
void model_from_ply(PlyBody body, const std::string& name, const ObjOptions& options, Model& model);

}  // namespace raster::detail
