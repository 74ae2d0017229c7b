#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include <cstdint>
#include <filesystem>
#include <span>

// PLY read by raster's own reader, in one pass over the file (doc/conventions.md#ply-reader).
namespace raster {

// ASCII and binary PLY in either byte order: vertices' x y z, normals, colours and texture
// coordinates, faces' corners; a PLY without faces is a point cloud. The few things only
// assimp's reader gives meaning to (a TextureFile comment, material elements, triangle strips,
// per-face texture coordinates) go to read_scene_file. Throws std::runtime_error with one line
// naming the file, and the line or byte, for a file it cannot use.
[[nodiscard]] Model read_ply(const std::filesystem::path& path, const ObjOptions& options = {});

// The same from bytes in memory, named "<memory>" in messages. For tests and fuzzing.
[[nodiscard]] Model parse_ply(std::span<const std::uint8_t> bytes, const ObjOptions& options = {});

}  // namespace raster
