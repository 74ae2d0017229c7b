// The only file that includes nlohmann/json (glTF's sizes and indices); stays whole for that.
#include "io/gltf_structure.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>
#include <nlohmann/json.hpp>

namespace raster::detail {
namespace {

using Json = nlohmann::json;

// Thrown inside the checks and turned into the returned line.
struct Broken : std::runtime_error {
    using std::runtime_error::runtime_error;
};

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

const Json& array_of(const Json& root, const char* key) {
    static const Json kEmpty = Json::array();
    const auto found = root.find(key);
    if (found == root.end()) return kEmpty;
    if (!found->is_array()) throw Broken(std::string("its '") + key + "' is not an array");
    return *found;
}

// A whole number at `key`, or `fallback` where there is none.
std::uint64_t number_at(const Json& object, const char* key, const std::string& what, std::uint64_t fallback = 0) {
    const auto found = object.find(key);
    if (found == object.end()) return fallback;
    if (!found->is_number_unsigned()) throw Broken(what + "'s '" + key + "' is not a whole number of 0 or more");
    return found->get<std::uint64_t>();
}

// The index at `key` checked against `count`; nothing where there is none.
std::optional<std::uint64_t> index_at(const Json& object, const char* key, std::size_t count, const std::string& what,
                                      const char* of) {
    if (!object.is_object() || object.find(key) == object.end()) return std::nullopt;
    const std::uint64_t index = number_at(object, key, what);
    if (index >= count)
        throw Broken(what + " names " + of + " " + std::to_string(index) + ", but there are " + std::to_string(count));
    return index;
}

std::uint64_t component_bytes(std::uint64_t type, const std::string& what) {
    switch (type) {
    case 5120:
    case 5121: return 1;
    case 5122:
    case 5123: return 2;
    case 5125:
    case 5126: return 4;
    default: throw Broken(what + " has component type " + std::to_string(type) + ", which glTF does not define");
    }
}

std::uint64_t components(const Json& accessor, const std::string& what) {
    const std::string type = accessor.value("type", std::string());
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    throw Broken(what + " has type '" + type.substr(0, 16) + "', which glTF does not define");
}

// Each buffer's declared length, checked against the bytes behind it.
std::vector<std::uint64_t> buffer_lengths(
    const Json& root, std::optional<std::uint64_t> binary_chunk,
    const std::function<std::optional<std::uint64_t>(std::string_view)>& external_size) {
    std::vector<std::uint64_t> lengths;
    const Json& buffers = array_of(root, "buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const std::string what = "buffer " + std::to_string(i);
        const std::uint64_t length = number_at(buffers[i], "byteLength", what);
        const auto uri = buffers[i].is_object() ? buffers[i].find("uri") : buffers[i].end();
        std::optional<std::uint64_t> there;
        if (uri == buffers[i].end() || !uri->is_string()) {
            there = i == 0 && binary_chunk ? *binary_chunk : 0;
        } else if (const std::string text = uri->get<std::string>(); text.starts_with("data:")) {
            const std::size_t comma = text.find(',');
            there = comma == std::string::npos ? 0 : (text.size() - comma - 1) / 4 * 3 + 2;
        } else {
            there = external_size(text);
        }
        if (there && length > *there) {
            throw Broken(what + " claims " + std::to_string(length) + " bytes, but only " + std::to_string(*there) +
                         " are there");
        }
        lengths.push_back(length);
    }
    return lengths;
}

struct View {
    std::uint64_t length;
    std::uint64_t stride;
};

std::vector<View> buffer_views(const Json& root, const std::vector<std::uint64_t>& buffers) {
    std::vector<View> views;
    const Json& list = array_of(root, "bufferViews");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "buffer view " + std::to_string(i);
        const std::uint64_t buffer = index_at(list[i], "buffer", buffers.size(), what, "buffer").value_or(UINT64_MAX);
        if (buffer == UINT64_MAX) throw Broken(what + " names no buffer");
        const std::uint64_t offset = number_at(list[i], "byteOffset", what),
                            length = number_at(list[i], "byteLength", what);
        if (offset > buffers[buffer] || length > buffers[buffer] - offset)
            throw Broken(what + " runs past the end of buffer " + std::to_string(buffer));
        const std::uint64_t stride = number_at(list[i], "byteStride", what);
        if (stride != 0 && (stride < 4 || stride > 252))
            throw Broken(what + " has a byte stride of " + std::to_string(stride) + ", outside 4..252");
        views.push_back({length, stride});
    }
    return views;
}

// `count` items of `size` bytes, `stride` apart, from `offset` in a view of `length` bytes.
bool fits(std::uint64_t offset, std::uint64_t count, std::uint64_t stride, std::uint64_t size, std::uint64_t length) {
    if (count == 0) return offset <= length;
    if (offset > length || size > length - offset) return false;
    return count - 1 <= (length - offset - size) / std::max<std::uint64_t>(stride, 1);
}

void check_accessors(const Json& root, const std::vector<View>& views) {
    const Json& list = array_of(root, "accessors");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "accessor " + std::to_string(i);
        const Json& accessor = list[i];
        if (!accessor.is_object()) throw Broken(what + " is not an object");
        const std::uint64_t element =
            component_bytes(number_at(accessor, "componentType", what), what) * components(accessor, what);
        const std::uint64_t count = number_at(accessor, "count", what);
        if (const auto view = index_at(accessor, "bufferView", views.size(), what, "buffer view")) {
            const std::uint64_t stride = views[*view].stride != 0 ? views[*view].stride : element;
            if (!fits(number_at(accessor, "byteOffset", what), count, stride, element, views[*view].length)) {
                throw Broken(what + " reads " + std::to_string(count) + " items past the end of buffer view " +
                             std::to_string(*view));
            }
        } else if (count > (std::uint64_t{1} << 30) / element) {
            throw Broken(what + " claims " + std::to_string(count) + " items with no data behind them");
        }
        const auto sparse = accessor.find("sparse");
        if (sparse == accessor.end()) continue;
        const std::uint64_t changed = number_at(*sparse, "count", what + "'s sparse part");
        if (changed > count)
            throw Broken(what + " changes " + std::to_string(changed) + " of its " + std::to_string(count) + " items");
        for (const char* part : {"indices", "values"}) {
            const auto found = sparse->find(part);
            if (found == sparse->end()) throw Broken(what + "'s sparse part has no " + part);
            const std::string where = what + "'s sparse " + part;
            const auto view = index_at(*found, "bufferView", views.size(), where, "buffer view");
            if (!view) throw Broken(where + " name no buffer view");
            const std::uint64_t size = std::string_view(part) == "indices"
                                           ? component_bytes(number_at(*found, "componentType", where), where)
                                           : element;
            if (!fits(number_at(*found, "byteOffset", where), changed, size, size, views[*view].length)) {
                throw Broken(where + " run past the end of buffer view " + std::to_string(*view));
            }
        }
    }
}

void check_indices(const Json& root) {
    const std::size_t accessors = array_of(root, "accessors").size(), nodes = array_of(root, "nodes").size();
    const std::size_t meshes = array_of(root, "meshes").size(), materials = array_of(root, "materials").size();
    const std::size_t textures = array_of(root, "textures").size(), skins = array_of(root, "skins").size();
    const Json& mesh_list = array_of(root, "meshes");
    for (std::size_t m = 0; m < mesh_list.size(); ++m) {
        const std::string what = "mesh " + std::to_string(m);
        for (const Json& primitive : mesh_list[m].is_object() ? array_of(mesh_list[m], "primitives") : Json::array()) {
            if (!primitive.is_object()) throw Broken(what + " has a primitive that is not an object");
            index_at(primitive, "indices", accessors, what, "accessor");
            index_at(primitive, "material", materials, what, "material");
            const Json attributes = primitive.value("attributes", Json::object());
            for (const auto& [name, index] : attributes.items()) {
                if (!index.is_number_unsigned() || index.get<std::uint64_t>() >= accessors)
                    throw Broken(what + "'s " + name.substr(0, 32) + " names no accessor it has");
            }
            for (const Json& target : array_of(primitive, "targets")) {
                for (const auto& [name, index] : target.items()) {
                    if (!index.is_number_unsigned() || index.get<std::uint64_t>() >= accessors)
                        throw Broken(what + "'s morph target names no accessor it has");
                }
            }
        }
    }
    for (const Json& material : array_of(root, "materials")) {
        const Json pbr = material.is_object() ? material.value("pbrMetallicRoughness", Json::object()) : Json::object();
        for (const Json* holder : {&pbr, &material}) {
            for (const char* key : {"baseColorTexture", "metallicRoughnessTexture", "normalTexture", "occlusionTexture",
                                    "emissiveTexture"}) {
                if (holder->is_object() && holder->contains(key))
                    index_at((*holder)[key], "index", textures, "a material", "texture");
            }
        }
    }
    const std::size_t images = array_of(root, "images").size(), samplers = array_of(root, "samplers").size();
    for (const Json& texture : array_of(root, "textures")) {
        index_at(texture, "source", images, "a texture", "image");
        index_at(texture, "sampler", samplers, "a texture", "sampler");
    }
    for (const Json& node : array_of(root, "nodes")) {
        index_at(node, "mesh", meshes, "a node", "mesh");
        index_at(node, "skin", skins, "a node", "skin");
    }
    const Json& skin_list = array_of(root, "skins");
    for (std::size_t s = 0; s < skin_list.size(); ++s) {
        const std::string what = "skin " + std::to_string(s);
        const Json& joints = array_of(skin_list[s], "joints");
        for (const Json& joint : joints) {
            if (!joint.is_number_unsigned() || joint.get<std::uint64_t>() >= nodes)
                throw Broken(what + " names a joint that is no node");
        }
        index_at(skin_list[s], "skeleton", nodes, what, "node");
        if (const auto matrices = index_at(skin_list[s], "inverseBindMatrices", accessors, what, "accessor")) {
            if (number_at(array_of(root, "accessors")[*matrices], "count", what) < joints.size()) {
                throw Broken(what + " has " + std::to_string(joints.size()) +
                             " joints but fewer inverse bind matrices");
            }
        }
    }
    for (const Json& animation : array_of(root, "animations")) {
        const std::size_t animation_samplers = array_of(animation, "samplers").size();
        for (const Json& sampler : array_of(animation, "samplers")) {
            index_at(sampler, "input", accessors, "an animation sampler", "accessor");
            index_at(sampler, "output", accessors, "an animation sampler", "accessor");
        }
        for (const Json& channel : array_of(animation, "channels")) {
            index_at(channel, "sampler", animation_samplers, "an animation channel", "sampler");
            if (channel.is_object() && channel.contains("target"))
                index_at(channel["target"], "node", nodes, "an animation channel", "node");
        }
    }
}

// Node depth and how many node instances the scenes expand to, found without recursion.
void check_node_graph(const Json& root) {
    const Json& nodes = array_of(root, "nodes");
    const std::size_t n = nodes.size();
    std::vector<std::vector<std::uint64_t>> children(n);
    std::vector<bool> has_parent(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (const Json& child : array_of(nodes[i], "children")) {
            if (!child.is_number_unsigned() || child.get<std::uint64_t>() >= n)
                throw Broken("node " + std::to_string(i) + " names a child that is no node");
            children[i].push_back(child.get<std::uint64_t>());
            has_parent[child.get<std::size_t>()] = true;
        }
    }
    enum : std::uint8_t { unseen, open, done };
    std::vector<std::uint8_t> state(n, unseen);
    std::vector<std::uint64_t> instances(n, 1), depth(n, 1);
    for (std::size_t start = 0; start < n; ++start) {
        if (state[start] != unseen) continue;
        std::vector<std::pair<std::size_t, std::size_t>> stack{{start, 0}};  // node, next child
        state[start] = open;
        while (!stack.empty()) {
            auto& [node, next] = stack.back();
            if (next < children[node].size()) {
                const auto child = static_cast<std::size_t>(children[node][next++]);
                if (state[child] == open) throw Broken("its node hierarchy loops (node " + std::to_string(child) + ")");
                if (state[child] == unseen) {
                    state[child] = open;
                    stack.emplace_back(child, 0);
                }
                continue;
            }
            for (const std::uint64_t child : children[node]) {
                instances[node] = std::min(instances[node] + instances[child], kMaxGltfNodeInstances + 1);
                depth[node] = std::max(depth[node], depth[child] + 1);
            }
            if (depth[node] > kMaxGltfNodeDepth)
                throw Broken("its nodes nest more than " + std::to_string(kMaxGltfNodeDepth) + " deep");
            state[node] = done;
            stack.pop_back();
        }
    }
    std::uint64_t total = 0;
    const Json& scenes = array_of(root, "scenes");
    for (const Json& scene : scenes) {
        for (const Json& node : array_of(scene, "nodes")) {
            if (!node.is_number_unsigned() || node.get<std::uint64_t>() >= n)
                throw Broken("a scene names a node it lacks");
            total = std::min(total + instances[node.get<std::size_t>()], kMaxGltfNodeInstances + 1);
        }
    }
    if (scenes.empty()) {
        for (std::size_t i = 0; i < n; ++i)
            total = has_parent[i] ? total : std::min(total + instances[i], kMaxGltfNodeInstances + 1);
    }
    if (total > kMaxGltfNodeInstances) {
        throw Broken("its shared nodes expand to more than " + std::to_string(kMaxGltfNodeInstances) +
                     " node instances");
    }
    index_at(root, "scene", scenes.size(), "the file", "scene");
}

std::uint32_t word_at(std::span<const std::uint8_t> bytes, std::size_t at) {
    std::uint32_t word = 0;
    std::memcpy(&word, bytes.data() + at, sizeof word);
    return word;
}

}  // namespace

std::string gltf_structure_problem(
    std::span<const std::uint8_t> bytes, bool binary,
    const std::function<std::optional<std::uint64_t>(std::string_view uri)>& external_size,
    std::vector<std::string>* extensions) {
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
        const std::vector<View> views = buffer_views(root, buffer_lengths(root, binary_chunk, external_size));
        check_accessors(root, views);
        for (const char* list : {"extensionsUsed", "extensionsRequired"}) {
            for (const Json& name : array_of(root, list)) {
                if (extensions == nullptr || !name.is_string()) continue;
                const std::string named = name.get<std::string>();
                if (std::find(extensions->begin(), extensions->end(), named) == extensions->end())
                    extensions->push_back(named);
            }
        }
        check_indices(root);
        check_node_graph(root);
        for (const Json& image : array_of(root, "images"))
            index_at(image, "bufferView", views.size(), "an image", "buffer view");
    } catch (const Broken& problem) {
        return problem.what();
    } catch (const Json::exception& problem) {
        return std::string("its JSON is not laid out as glTF's: ") + problem.what();
    }
    return "";
}

}  // namespace raster::detail
