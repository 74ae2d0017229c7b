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

// What a PLY's body holds, for messages when the reader finds nothing in it.
struct PlyShape {
    std::uint64_t vertices = 0;  // as the header declares
    std::string cut_short;       // "the PLY data is cut short: ..." when the body ends before the elements do, else ""
};

// "" when no element count is more than the bytes after the header can hold (every property at
// its smallest) and no list is longer than the bytes after its length (a binary body walked
// byte by byte, an ASCII one line by line); else the first that is, before a reader allocates
// what a few hundred bytes claim. A body that is merely cut short passes (the reader keeps what
// is there) and is noted in `shape`. Call after ply_header_problem passed.
[[nodiscard]] std::string ply_counts_problem(std::span<const std::uint8_t> bytes, PlyShape* shape = nullptr);

}  // namespace raster::detail
