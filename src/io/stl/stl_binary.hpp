#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/ply/ply_bytes.hpp"

#include <cstdint>
#include <span>
#include <string>

// A binary STL: an 80-byte header, a triangle count, and 50 bytes for each triangle (its normal,
// three corners and an attribute word), read in one pass over bounded blocks (doc/conventions.md#stl-reader).
namespace raster::detail {

inline constexpr std::uint64_t kStlHeaderBytes = 84;
inline constexpr std::uint64_t kStlRecordBytes = 50;

// The triangle count a binary STL's first 84 bytes claim; 0 for fewer bytes.
[[nodiscard]] std::uint32_t stl_claimed_count(std::span<const std::uint8_t> head) noexcept;

// Whether a file of `size` bytes starting with `head` is a binary STL: its count fits its size exactly.
[[nodiscard]] bool is_binary_stl(std::span<const std::uint8_t> head, std::uint64_t size) noexcept;

// The model in `bytes`, positioned at the file's start, of a file that is_binary_stl; throws
// std::runtime_error naming `name` and the byte for a file that ends early or a corner that is not finite.
[[nodiscard]] Model read_binary_stl(PlyBytes& bytes, const std::string& name, const ObjOptions& options, Model model);

}  // namespace raster::detail
