#pragma once

#include "io/gltf/gltf_facts.hpp"
#include "io/gltf/json_fields.hpp"

#include <string>
#include <vector>

namespace raster::detail::gltf_json {

// Each camera placed by the first node that holds it (world transform through its parents,
// which check_node_graph has found loop-free); a camera no node holds stands at the origin
// looking down -Z. A lens field out of range keeps raster's default and is named in `problems`.
std::vector<ModelCamera> camera_facts(const Json& root, std::vector<std::string>& problems);

}  // namespace raster::detail::gltf_json
