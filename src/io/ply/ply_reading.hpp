#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/ply/ply_body.hpp"
#include "io/ply/ply_layout.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>

// A PLY read by raster's own reader in the calling process, which needs no child to contain it
// (doc/conventions.md#reader-process).
namespace raster::detail {

// The least the model's arrays take for the header's counts: 24 bytes a vertex (its position and
// normal), 36 a face (one triangle); what --max-memory is checked against before reading. A count
// is taken at most as large as `body_bytes` can hold, so a lying one gets the reader's own message.
[[nodiscard]] std::uint64_t least_ply_memory(const PlyLayout& layout, std::uint64_t body_bytes) noexcept;

// What the mesh of a body read takes at least: 24 bytes a vertex, 36 a triangle of its faces.
[[nodiscard]] std::uint64_t ply_body_memory(const PlyBody& body) noexcept;

// The model, read here when raster's own reader takes the whole file, else by `elsewhere` (assimp
// in a child). Throws std::runtime_error with one line when the counts need more than
// options.limits allow, or the file cannot be read.
[[nodiscard]] Model read_ply_here(const std::filesystem::path& path, const ObjOptions& options,
                                  const std::function<Model()>& elsewhere);

}  // namespace raster::detail
