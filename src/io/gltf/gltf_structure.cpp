#include "io/gltf/gltf_structure.hpp"

#include "io/gltf/gltf_buffers.hpp"
#include "io/gltf/gltf_camera_facts.hpp"
#include "io/gltf/gltf_graph.hpp"
#include "io/gltf/gltf_material_facts.hpp"
#include "io/gltf/json_fields.hpp"

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

namespace raster::detail {
namespace {

using gltf_json::array_of;
using gltf_json::Broken;
using gltf_json::index_at;
using gltf_json::Json;
using gltf_json::View;

// How deep the JSON nests, scanned without parsing: a recursive parser must never see more.
int json_depth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > kMaxJsonDepth) return deepest;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

std::uint32_t word_at(std::span<const std::uint8_t> bytes, std::size_t at) {
    std::uint32_t word = 0;
    std::memcpy(&word, bytes.data() + at, sizeof word);
    return word;
}

}  // namespace

std::string gltf_structure_problem(
    std::span<const std::uint8_t> bytes, bool binary,
    const std::function<std::optional<std::uint64_t>(std::string_view uri)>& external_size, GltfFacts* facts) {
    try {
        std::span<const std::uint8_t> json_bytes = bytes;
        std::optional<std::uint64_t> binary_chunk;
        if (binary) {
            if (bytes.size() < 20 || word_at(bytes, 0) != 0x46546C67U) throw Broken("is not a glTF binary file");
            if (word_at(bytes, 4) != 2)
                throw Broken("is glTF " + std::to_string(word_at(bytes, 4)) + ".0 binary; raster reads glTF 2.0");
            if (word_at(bytes, 8) > bytes.size())
                throw Broken("claims " + std::to_string(word_at(bytes, 8)) + " bytes but holds " +
                             std::to_string(bytes.size()));
            const std::size_t end = word_at(bytes, 8);
            for (std::size_t at = 12; at + 8 <= end;) {
                const std::uint64_t length = word_at(bytes, at), type = word_at(bytes, at + 4);
                if (length > end - at - 8)
                    throw Broken("has a chunk of " + std::to_string(length) + " bytes that runs past its end");
                if (at == 12 && type != 0x4E4F534AU) throw Broken("does not begin with its JSON chunk");
                if (at == 12) json_bytes = bytes.subspan(at + 8, static_cast<std::size_t>(length));
                if (at > 12 && type == 0x004E4942U && !binary_chunk) binary_chunk = length;
                at += 8 + static_cast<std::size_t>(length);
            }
            if (json_bytes.size() == bytes.size()) throw Broken("has no JSON chunk");
        }
        const std::string_view text(reinterpret_cast<const char*>(json_bytes.data()), json_bytes.size());
        if (json_depth(text) > kMaxJsonDepth)
            throw Broken("its JSON nests more than " + std::to_string(kMaxJsonDepth) + " deep");
        const Json root = Json::parse(text, nullptr, false);
        if (root.is_discarded() || !root.is_object()) throw Broken("its JSON does not parse as an object");
        const Json asset = root.value("asset", Json::object());
        if (const auto version = asset.find("version");
            version != asset.end() && version->is_string() && version->get<std::string>().starts_with("1")) {
            throw Broken("is glTF " + version->get<std::string>().substr(0, 8) + "; raster reads glTF 2.0");
        }
        if (const auto buffers = root.find("buffers"); buffers != root.end() && buffers->is_object()) {
            throw Broken("is glTF 1.0 (its buffers are named, not listed); raster reads glTF 2.0");
        }
        const std::vector<View> views =
            gltf_json::buffer_views(root, gltf_json::buffer_lengths(root, binary_chunk, external_size));
        gltf_json::check_accessors(root, views);
        for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
            for (const Json& name : array_of(root, list)) {
                if (facts == nullptr || !name.is_string()) continue;
                const std::string named = name.get<std::string>();
                if (std::find(facts->extensions.begin(), facts->extensions.end(), named) == facts->extensions.end())
                    facts->extensions.push_back(named);
            }
        }
        gltf_json::check_indices(root);
        gltf_json::check_node_graph(root);
        for (const Json& image : array_of(root, "images"))
            index_at(image, "bufferView", views.size(), "an image", "buffer view");
        // Read once the graph is known to hold together, and always: a transform assimp would abort on is refused.
        std::vector<GltfMaterialFacts> materials = gltf_json::material_facts(root);
        std::vector<std::string> camera_problems;
        std::vector<ModelCamera> cameras = gltf_json::camera_facts(root, camera_problems);
        if (facts != nullptr) {  // assimp may open the file twice: the last reading stands
            facts->materials = std::move(materials);
            facts->cameras = std::move(cameras);
            facts->camera_problems = std::move(camera_problems);
        }
    } catch (const Broken& problem) {
        return problem.what();
    } catch (const Json::exception& problem) {
        return std::string("its JSON is not laid out as glTF's: ") + problem.what();
    }
    return "";
}

}  // namespace raster::detail