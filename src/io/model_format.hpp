#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

// Which format a model file is, decided before any reader runs: by the name's ending, then
// checked against the first bytes, so a file renamed .glb is never handed to every reader assimp has.
namespace raster::detail {

// `other`: one of the further formats the Open Asset Import Library reads, named by its ending.
enum class ModelFormat { obj, gltf, glb, stl, ply, other };

// The format a file name ends in (any letter case); throws std::runtime_error for an ending
// raster does not read: a format it knows says why, any other lists the endings it reads.
[[nodiscard]] ModelFormat model_format_of(const std::filesystem::path& path);

// "OBJ", "glTF", "glTF binary", "STL", "PLY", "Collada", ...: the reader's name in messages.
[[nodiscard]] std::string format_name(ModelFormat format, const std::filesystem::path& path = {});

// "a glTF model", "an STL model": the article as the name is said.
[[nodiscard]] std::string a_model(const std::string& name);

// The ending in lower case, with its dot: ".obj".
[[nodiscard]] std::string ending_of(const std::filesystem::path& path);

// The bytes checked by content_problem: enough for every signature it knows.
inline constexpr std::size_t kSignatureBytes = 96;

// "" when the first bytes of a file of `file_size` bytes fit `format`, else one line saying
// what they look like instead: "looks like an OFF model, not glTF binary".
[[nodiscard]] std::string content_problem(ModelFormat format, std::span<const std::uint8_t> head,
                                          std::uintmax_t file_size, const std::filesystem::path& path = {});

// Whether the linked Open Asset Import Library has a reader claiming `ending` (".dae"); defined
// in src/io/assimp/, the one folder that includes it.
[[nodiscard]] bool assimp_claims(const std::string& ending);

}  // namespace raster::detail
