#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/ply/ply_bytes.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

// A model file opened for one of raster's own readers (PLY, STL), which read it once in blocks.
namespace raster::detail {

// Reads with `read`: the file's blocks, its size when opened, its printable name and a model
// holding its source. Opened as any model is (InputFile's rules); throws std::runtime_error with
// one line that names the file.
using BlockReader = std::function<Model(PlyBytes& bytes, std::uint64_t size, const std::string& name, Model model)>;
[[nodiscard]] Model read_model_blocks(const std::filesystem::path& path, const ObjOptions& options,
                                      const BlockReader& read);

// Bytes in memory handed out as a file's blocks, for tests and fuzzing.
[[nodiscard]] PlyBytes blocks_in_memory(std::span<const std::uint8_t> bytes);

}  // namespace raster::detail
