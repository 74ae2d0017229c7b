#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

// Which format a model file is, decided before any reader runs: by the name's ending, then
// checked against the first bytes, so a file renamed .glb is never handed to every reader assimp has.
namespace raster::detail {

enum class ModelFormat { obj, gltf, glb, stl, ply };

// The format a file name ends in (any letter case); throws std::runtime_error listing the
// endings raster reads for any other.
[[nodiscard]] ModelFormat model_format_of(const std::filesystem::path& path);

// "OBJ", "glTF", "glTF binary", "STL", "PLY": the reader's name in messages.
[[nodiscard]] std::string format_name(ModelFormat format);

// The bytes checked by content_problem: enough for every signature it knows.
inline constexpr std::size_t kSignatureBytes = 96;

// "" when the first bytes of a file of `file_size` bytes fit `format`, else one line saying
// what they look like instead: "looks like an OFF model, not glTF binary".
[[nodiscard]] std::string content_problem(ModelFormat format, std::span<const std::uint8_t> head,
                                          std::uintmax_t file_size);

}  // namespace raster::detail
