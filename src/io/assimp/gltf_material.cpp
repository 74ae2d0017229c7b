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

// The file's own word on the material: each map's KHR_texture_transform, KHR_materials_emissive_strength
// (doc/conventions.md#texture-transform, doc/conventions.md#emissive-strength).
void apply_facts(const aiMaterial& m, const GltfFacts& gltf, const std::string& material, MetallicRoughness& read,
                 std::vector<std::string>& warnings) {
    bool ambiguous = false;
    const GltfMaterialFacts* facts = facts_of(m, gltf, ambiguous);
    if (ambiguous) {
        warnings.push_back(material + ": several of the file's materials have this name and differ in their "
                                      "extensions; drawn without KHR_texture_transform and emissive strength");
    }
    if (facts == nullptr) return;
    for (const std::string& problem : facts->problems) warnings.push_back(material + ": " + problem);
    for (std::size_t map = 0; map < kGltfMaps.size(); ++map) {
        read.*kGltfMaps[map].transform = facts->transforms[map];
        if (facts->coordinate_sets[map] != 0) {
            warnings.push_back(material + ": its " + kGltfMapNames[map] + " map reads texture coordinate set " +
                               std::to_string(facts->coordinate_sets[map]) +
                               "; raster carries only the first set, and reads it there");
        }
    }
    if (!facts->emissive_strength) return;
    const double strength = *facts->emissive_strength;
    if (std::isfinite(strength) && strength >= 0.0 && strength <= 3.0e38) {
        read.emissive = read.emissive * static_cast<float>(strength);
    } else {
        std::ostringstream line;
        line << material << ": emissiveStrength " << strength << " is not a finite number of 0 or more; drawn as 1";
        warnings.push_back(line.str());
    }
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

const GltfMaterialFacts* facts_of(const aiMaterial& m, const GltfFacts& gltf, bool& ambiguous) {
    const std::string name = m.GetName().C_Str();
    const GltfMaterialFacts* found = nullptr;
    ambiguous = false;
    for (const GltfMaterialFacts& facts : gltf.materials) {
        if (facts.name != name) continue;
        if (found != nullptr && !(*found == facts)) {
            ambiguous = true;
            return nullptr;
        }
        found = &facts;
    }
    return found;
}

MetallicRoughness gltf_factors(const aiMaterial& m, const std::string& name, const GltfFacts* gltf,
                               std::vector<std::string>& warnings) {
    MetallicRoughness read;  // the specification's defaults where the file says nothing
    aiColor4D base(1.0F, 1.0F, 1.0F, 1.0F);
    if (m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) read.base_colour = {base.r, base.g, base.b};
    m.Get(AI_MATKEY_METALLIC_FACTOR, read.metallic);
    m.Get(AI_MATKEY_ROUGHNESS_FACTOR, read.roughness);
    aiColor3D emissive(0.0F, 0.0F, 0.0F);
    if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS) read.emissive = {emissive.r, emissive.g, emissive.b};
    m.Get(AI_MATKEY_GLTF_TEXTURE_STRENGTH(aiTextureType_LIGHTMAP, 0), read.occlusion_strength);
    m.Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), read.normal_scale);
    const std::string material = name + ": material '" + printable(m.GetName().C_Str(), 80) + "'";
    if (gltf != nullptr) apply_facts(m, *gltf, material, read, warnings);
    const MetallicRoughness usable = read.usable();
    check(read.base_colour.r, usable.base_colour.r, "baseColorFactor red", material, warnings);
    check(read.base_colour.g, usable.base_colour.g, "baseColorFactor green", material, warnings);
    check(read.base_colour.b, usable.base_colour.b, "baseColorFactor blue", material, warnings);
    check(read.metallic, usable.metallic, "metallicFactor", material, warnings);
    check(read.roughness, usable.roughness, "roughnessFactor", material, warnings);
    check(read.occlusion_strength, usable.occlusion_strength, "occlusion strength", material, warnings);
    check(read.normal_scale, usable.normal_scale, "normal scale", material, warnings);
    for (const float c : {read.emissive.r, read.emissive.g, read.emissive.b})
        check(c, c >= 0.0F ? c : 0.0F, "emissiveFactor", material, warnings);
    return usable;
}

}  // namespace raster::detail
