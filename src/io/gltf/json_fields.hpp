#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <nlohmann/json.hpp>

// Reading glTF's JSON fields, each checked as it is read; the folder that includes nlohmann/json.
namespace raster::detail::gltf_json {

using Json = nlohmann::json;

// Thrown inside the checks and turned into the returned line.
struct Broken : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline const Json& array_of(const Json& root, const char* key) {
    static const Json kEmpty = Json::array();
    const auto found = root.find(key);
    if (found == root.end()) return kEmpty;
    if (!found->is_array()) throw Broken(std::string("its '") + key + "' is not an array");
    return *found;
}

// A whole number at `key`, or `fallback` where there is none.
inline std::uint64_t number_at(const Json& object, const char* key, const std::string& what,
                               std::uint64_t fallback = 0) {
    const auto found = object.find(key);
    if (found == object.end()) return fallback;
    if (!found->is_number_unsigned()) throw Broken(what + "'s '" + key + "' is not a whole number of 0 or more");
    return found->get<std::uint64_t>();
}

// The index at `key` checked against `count`; nothing where there is none.
inline std::optional<std::uint64_t> index_at(const Json& object, const char* key, std::size_t count,
                                             const std::string& what, const char* of) {
    if (!object.is_object() || object.find(key) == object.end()) return std::nullopt;
    const std::uint64_t index = number_at(object, key, what);
    if (index >= count)
        throw Broken(what + " names " + of + " " + std::to_string(index) + ", but there are " + std::to_string(count));
    return index;
}

}  // namespace raster::detail::gltf_json
