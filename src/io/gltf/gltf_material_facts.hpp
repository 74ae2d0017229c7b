#pragma once

#include "io/gltf/gltf_facts.hpp"
#include "io/gltf/json_fields.hpp"

#include <vector>

namespace raster::detail::gltf_json {

// Each material's transforms, coordinate sets and emissive strength; a field not as the
// extension defines it is left at its default and named in the material's problems. Throws
// Broken for an offset or scale array that assimp 5.2.5 would abort on (fewer than two numbers).
std::vector<GltfMaterialFacts> material_facts(const Json& root);

}  // namespace raster::detail::gltf_json
