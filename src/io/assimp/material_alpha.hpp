#pragma once

#include <raster/shade/opacity.hpp>

#include <string>
#include <vector>

struct aiMaterial;

// A material's alpha as assimp gives it (doc/conventions.md#transparency): glTF's alphaMode,
// alphaCutoff and base colour alpha; other formats' opacity below 1 blends.
namespace raster::detail {

// `said` begins each warning: the file and the material.
[[nodiscard]] Opacity opacity_of(const aiMaterial& m, const std::string& said, std::vector<std::string>& warnings);

}  // namespace raster::detail
