#include "io/assimp/material_alpha.hpp"

#include "io/alpha_reading.hpp"

#include <string_view>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>

namespace raster::detail {

Opacity opacity_of(const aiMaterial& m, const std::string& said, std::vector<std::string>& warnings) {
    float alpha = 1.0F;
    if (aiColor4D base; m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) {
        alpha = base.a;
    } else if (m.Get(AI_MATKEY_OPACITY, alpha) != AI_SUCCESS) {
        alpha = 1.0F;
    }
    aiString mode;
    if (m.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) != AI_SUCCESS)  // not glTF: an opacity below 1 blends
        return blended_by(alpha, said + " has opacity", warnings);
    const std::string_view name(mode.C_Str());
    if (name == "OPAQUE") return {};
    const float factor = alpha_or(alpha, 1.0F, said + " has base colour alpha", warnings);
    if (name == "BLEND") return {AlphaMode::blend, factor, 0.5F};
    if (name == "MASK") {
        float cutoff = 0.5F;
        m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff);
        return {AlphaMode::mask, factor, alpha_or(cutoff, 0.5F, said + " has alphaCutoff", warnings)};
    }
    warnings.push_back(said + " has alphaMode '" + std::string(name.substr(0, 40)) +
                       "', not OPAQUE, MASK or BLEND; drawing it opaque");
    return {};
}

}  // namespace raster::detail
