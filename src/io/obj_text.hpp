#pragma once

#include <raster/io/input_file.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

// OBJ and MTL files as text: the rules they are read under, and failures said in raster's words.
namespace raster::detail {

// The rules for an OBJ or MTL file: capped, confined, and refused when its first bytes are a
// binary format's (an image, glTF, an archive, a program).
[[nodiscard]] InputRules text_rules(std::string role, std::string expected, const std::filesystem::path& confine);

// Notes a file the model names, whether or not it can be read: no output may replace it.
void note_named(std::vector<InputRecord>& sources, const std::filesystem::path& path, const char* role);

// Rethrows the exception being handled as one line that begins with the file's name.
[[noreturn]] void rethrow_named(const std::string& name);

}  // namespace raster::detail
