#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include <filesystem>
#include <string>

// The two halves of read_model: what runs in the reader's process, and how its messages name it.
namespace raster::detail {

// The format checked against the first bytes, then the format's reader, in this process.
[[nodiscard]] Model read_model_here(const std::filesystem::path& path, const ObjOptions& options);

// "glTF", "STL", ...: the reader's name in messages; throws for an ending raster does not read.
[[nodiscard]] std::string reader_name(const std::filesystem::path& path);

}  // namespace raster::detail
