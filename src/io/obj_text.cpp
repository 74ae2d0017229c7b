#include "io/obj_text.hpp"

#include <raster/io/obj_file.hpp>

#include <algorithm>
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

[[noreturn]] void rethrow_named(const std::string& name) {
    try {
        throw;
    } catch (const std::runtime_error& problem) {
        const std::string what = problem.what();
        throw std::runtime_error(what.starts_with(name + ":") ? what : name + ": " + what);
    }
}

}  // namespace raster::detail
