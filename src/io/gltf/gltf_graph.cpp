#include "io/gltf/gltf_graph.hpp"

#include "io/gltf/gltf_structure.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace raster::detail::gltf_json {

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

}  // namespace raster::detail::gltf_json
