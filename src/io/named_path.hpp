#pragma once

#include <filesystem>
#include <string_view>

// Paths as model files write them (doc/conventions.md#models): Windows separators, "./" in
// front, quotes, and letter case that differs from the file system.
namespace raster::detail {

// The file that `written` names relative to `directory`: the path as written if it exists;
// else, with quotes around it dropped and backslashes read as separators, the same path with
// each missing part matched to the one entry of its directory that differs only in letter case.
// Only the directories on the written path are listed, none under `confine` when it is set and
// they lie outside it. When nothing matches, the path as written, so that errors name it.
[[nodiscard]] std::filesystem::path resolve_named_path(const std::filesystem::path& directory, std::string_view written,
                                                       const std::filesystem::path& confine = {});

}  // namespace raster::detail
