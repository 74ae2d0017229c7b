#include "io/obj_text.hpp"

#include <raster/io/obj_file.hpp>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <utility>

namespace raster::detail {
namespace {

// Binary files people pass by mistake (images, glTF, archives, programs) are refused from their
// first bytes; OBJ and MTL have no signature of their own.
bool not_binary(std::span<const std::uint8_t> head) {
    const auto starts = [&](std::string_view magic) {
        return head.size() >= magic.size() &&
               std::equal(magic.begin(), magic.end(), head.begin(),
                          [](char m, std::uint8_t b) { return static_cast<std::uint8_t>(m) == b; });
    };
    return !(starts("\x89PNG") || starts("\xFF\xD8\xFF") || starts("GIF8") || starts("RIFF") || starts("glTF") ||
             starts("PK\x03\x04") || starts("\177ELF"));
}

}  // namespace

InputRules text_rules(std::string role, std::string expected, const std::filesystem::path& confine) {
    InputRules rules;
    rules.role = std::move(role);
    rules.max_bytes = kMaxModelFileBytes;
    rules.signature = not_binary;
    rules.signature_bytes = 8;
    rules.expected = std::move(expected);
    rules.confine = confine;
    return rules;
}

void note_named(std::vector<InputRecord>& sources, const std::filesystem::path& path, const char* role) {
    if (FileIdentity identity; identity_of(path, identity)) sources.push_back({path, identity, role});
}

// tinyobjloader fails a load only on an index it cannot read in a statement the survey does not
// check (vw): said in raster's words, with the line where its message has one.
std::runtime_error load_failure(const std::string& err, const std::string& name) {
    const std::size_t at = err.find("line ");
    std::size_t line = 0;
    if (at != std::string::npos) std::from_chars(err.data() + at + 5, err.data() + err.size(), line);
    if (line == 0) return std::runtime_error(name + ": not an OBJ model raster can read");
    return std::runtime_error(name + ":" + std::to_string(line) + ": a statement with an index raster cannot read");
}

[[noreturn]] void rethrow_named(const std::string& name) {
    try {
        throw;
    } catch (const std::runtime_error& problem) {
        const std::string what = problem.what();
        throw std::runtime_error(what.starts_with(name + ":") ? what : name + ": " + what);
    }
}

}  // namespace raster::detail
