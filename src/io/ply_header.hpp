#pragma once

#include <cstdint>
#include <span>
#include <string>

// PLY headers read by raster before assimp sees them: assimp 5.2.5 loops forever on a header
// without its end_header line, so only a header of known words reaches it.
namespace raster::detail {

// The longest header read, in bytes; real headers are a few hundred.
inline constexpr std::size_t kMaxPlyHeaderBytes = 64 * 1024;

// "" for a header that begins with ply and its format line, ends with end_header within
// kMaxPlyHeaderBytes, and whose element and property lines name decimal counts and known
// types; else why not, with its line. Other lines are skipped, as assimp skips them.
[[nodiscard]] std::string ply_header_problem(std::span<const std::uint8_t> bytes);

}  // namespace raster::detail
