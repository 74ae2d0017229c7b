#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// PLY headers read by raster before assimp sees them: assimp 5.2.5 loops forever on a header
// without its end_header line, so only a header of known words reaches it.
namespace raster::detail {

// The longest header read, in bytes; real headers are a few hundred.
inline constexpr std::size_t kMaxPlyHeaderBytes = 64 * 1024;

// "" for a header that begins with ply and its format line, ends with end_header within
// kMaxPlyHeaderBytes, and whose element and property lines name decimal counts and known
// types; else why not, with its line. Other lines are skipped, as assimp skips them.
[[nodiscard]] std::string ply_header_problem(std::span<const std::uint8_t> bytes);

// The words of one header line, split at spaces and tabs.
[[nodiscard]] std::vector<std::string_view> ply_words(std::string_view line);

// "" when no element count is larger than the bytes after the header and no list is longer than
// the bytes after its length (a binary body walked byte by byte, an ASCII one line by line);
// else the first that is, before a reader allocates what a few hundred bytes claim. A body
// that is merely cut short passes: the reader keeps what is there. Call after
// ply_header_problem passed.
[[nodiscard]] std::string ply_counts_problem(std::span<const std::uint8_t> bytes);

}  // namespace raster::detail
