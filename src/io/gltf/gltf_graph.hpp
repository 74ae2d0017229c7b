#pragma once

#include "io/gltf/json_fields.hpp"

// glTF's indices and node graph: what each object names exists, and the nodes neither loop,
// nest too deep nor expand to too many instances.
namespace raster::detail::gltf_json {

// Throws Broken for an index that names nothing the file has.
void check_indices(const Json& root);

// Node depth and how many node instances the scenes expand to, found without recursion; throws
// Broken past kMaxGltfNodeDepth or kMaxGltfNodeInstances, or for a loop.
void check_node_graph(const Json& root);

}  // namespace raster::detail::gltf_json
