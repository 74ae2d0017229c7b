#include "io/assimp/gltf_material.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>

namespace raster::detail {
namespace {

// Reads one factor; a value the usable material would change is named in a warning.
void check(float written, float usable, const char* field, const std::string& name,
           std::vector<std::string>& warnings) {
    if (written == usable || (std::isnan(written) && std::isnan(usable))) return;
    std::ostringstream line;
    line << name << ": " << field << " " << written << " is outside its range; drawn as " << usable;
    warnings.push_back(line.str());
}

}  // namespace

// A glTF metallic-roughness material as raster's Phong (doc/conventions.md#models): the base
// colour is diffuse as far as the surface is not metal; the highlight is 4 % white for a
// dielectric and the base colour for a metal, as sharp as the roughness allows.
LinearMaterial phong_from(const aiMaterial& m) {
    aiColor4D base(0.8F, 0.8F, 0.8F, 1.0F);
    if (m.Get(AI_MATKEY_BASE_COLOR, base) != AI_SUCCESS) m.Get(AI_MATKEY_COLOR_DIFFUSE, base);
    float metallic = 0.0F, roughness = 1.0F;
    const bool pbr = m.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
    if (pbr) m.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness);
    const auto usable = [](float v, float fallback) { return std::isfinite(v) ? std::clamp(v, 0.0F, 1.0F) : fallback; };
    metallic = usable(metallic, 0.0F);
    roughness = usable(roughness, 1.0F);
    const LinearRgb colour{std::max(0.0F, usable(base.r, 0.8F)), std::max(0.0F, usable(base.g, 0.8F)),
                           std::max(0.0F, usable(base.b, 0.8F))};
    LinearMaterial material{LinearRgb{}, colour * (1.0F - metallic), LinearRgb{}, std::nullopt};
    const float alpha = roughness * roughness;
    if (pbr && alpha < 0.95F) {
        const float f0 = 0.04F * (1.0F - metallic);
        material.specular = LinearRgb{f0, f0, f0} + colour * metallic;
        material.shininess = std::min(2.0F / std::max(alpha * alpha, 1e-4F) - 2.0F, 2048.0F);
    }
    return material;
}

bool is_gltf_material(const aiMaterial& m) {
    aiString mode;
    return m.Get(AI_MATKEY_GLTF_ALPHAMODE, mode) == AI_SUCCESS;
}

MetallicRoughness gltf_factors(const aiMaterial& m, const std::string& name, std::vector<std::string>& warnings) {
    MetallicRoughness read;  // the specification's defaults where the file says nothing
    aiColor4D base(1.0F, 1.0F, 1.0F, 1.0F);
    if (m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) read.base_colour = {base.r, base.g, base.b};
    m.Get(AI_MATKEY_METALLIC_FACTOR, read.metallic);
    m.Get(AI_MATKEY_ROUGHNESS_FACTOR, read.roughness);
    aiColor3D emissive(0.0F, 0.0F, 0.0F);
    if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS) read.emissive = {emissive.r, emissive.g, emissive.b};
    float strength = 1.0F;  // KHR_materials_emissive_strength
    if (m.Get(AI_MATKEY_EMISSIVE_INTENSITY, strength) == AI_SUCCESS && std::isfinite(strength) && strength >= 0.0F)
        read.emissive = read.emissive * strength;
    m.Get(AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0), read.occlusion_strength);
    m.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), read.normal_scale);
    const MetallicRoughness usable = read.usable();
    const std::string material = name + ": material '" + printable(m.GetName().C_Str(), 80) + "'";
    check(read.base_colour.r, usable.base_colour.r, "baseColorFactor red", material, warnings);
    check(read.base_colour.g, usable.base_colour.g, "baseColorFactor green", material, warnings);
    check(read.base_colour.b, usable.base_colour.b, "baseColorFactor blue", material, warnings);
    check(read.metallic, usable.metallic, "metallicFactor", material, warnings);
    check(read.roughness, usable.roughness, "roughnessFactor", material, warnings);
    check(read.occlusion_strength, usable.occlusion_strength, "occlusion strength", material, warnings);
    check(read.normal_scale, usable.normal_scale, "normal scale", material, warnings);
    for (const float c : {read.emissive.r, read.emissive.g, read.emissive.b})
        check(c, c >= 0.0F ? c : 0.0F, "emissiveFactor", material, warnings);
    for (const GltfMap& map : kGltfMaps) {  // every map is read at the mesh's own coordinates
        aiUVTransform moved;
        if (m.Get(AI_MATKEY_UVTRANSFORM(map.type, 0), moved) != AI_SUCCESS) continue;
        if (moved.mTranslation == aiVector2D(0, 0) && moved.mScaling == aiVector2D(1, 1) && moved.mRotation == 0.0F)
            continue;
        warnings.push_back(material + ": KHR_texture_transform is not applied yet; its maps are read untransformed");
        break;
    }
    return usable;
}

}  // namespace raster::detail
