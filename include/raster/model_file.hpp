#pragma once

#include <raster/model.hpp>
#include <raster/obj_file.hpp>

#include <filesystem>

// Models of every format `render` reads, chosen by the file name's ending
// (doc/conventions.md#models).
namespace raster {

// glTF 2.0 (.gltf with its buffers and images, .glb), STL and PLY through the Open Asset Import
// Library: every node's meshes placed by the node's matrices, base colour and its texture (sRGB)
// as the diffuse colour and map, metallic-roughness as a Phong highlight, normals and texture
// coordinates where the file has them. Every file it opens goes through InputFile. Throws
// std::runtime_error with one line naming the file for a file it cannot use.
[[nodiscard]] Model read_scene_file(const std::filesystem::path& path, const ObjOptions& options = {});

// read_obj for .obj (any letter case), read_scene_file for .gltf, .glb, .stl and .ply; any other
// ending is refused with the list of those it reads.
[[nodiscard]] Model read_model(const std::filesystem::path& path, const ObjOptions& options = {});

}  // namespace raster
