#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include <cstdint>
#include <filesystem>
#include <span>

// STL read by raster's own reader, in one pass over the file (doc/conventions.md#stl-reader).
namespace raster {

// Binary STL (its triangle count fits its size exactly, whatever its header says) and ASCII STL
// (text beginning "solid"): every triangle three vertices of its own, as assimp's reader gave
// them, with the file's normal or the facet's, and a binary file's face colours. Throws
// std::runtime_error with one line naming the file, and the line or byte, for a file it cannot use.
[[nodiscard]] Model read_stl(const std::filesystem::path& path, const ObjOptions& options = {});

// The same from bytes in memory, named "<memory>" in messages. For tests and fuzzing.
[[nodiscard]] Model parse_stl(std::span<const std::uint8_t> bytes, const ObjOptions& options = {});

}  // namespace raster
