#pragma once

#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/metallic_roughness.hpp>
#include <raster/shade/texture.hpp>

#include "io/gltf/gltf_facts.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>
#include <assimp/material.h>

// glTF 2.0's metallic-roughness materials as assimp 5.2's importer hands them on
// (doc/conventions.md#metallic-roughness).
namespace raster::detail {

// A material as raster's Phong (doc/conventions.md#models), for formats other than glTF and for
// readers of the Phong fields: base colour as diffuse as far as the surface is not metal, the
// highlight 4 % white for a dielectric and the base colour for a metal, as sharp as the roughness allows.
[[nodiscard]] LinearMaterial phong_from(const aiMaterial& m);

// Whether assimp read the material from glTF 2.0: its importer gives every material, the
// default one included, an alpha mode; other formats keep Phong.
[[nodiscard]] bool is_gltf_material(const aiMaterial& m);

// The material's factors (its maps are the caller's to load): base colour, metallic, roughness,
// emissive, occlusion strength, normal scale; and from `gltf`, what raster read of the file's
// JSON (none for assimp's default material), each map's KHR_texture_transform and
// KHR_materials_emissive_strength (assimp 5.2.5 reads neither as the extensions define them).
// A factor outside its range or not a number is made usable (MetallicRoughness::usable()) and
// named in `warnings`, one line each, prefixed with `name`.
[[nodiscard]] MetallicRoughness gltf_factors(const aiMaterial& m, const std::string& name, const GltfFacts* gltf,
                                             std::vector<std::string>& warnings);

// The facts of the file's material that assimp read as `m`, found by name: assimp 5.2 lists a
// file's materials as it first meets them, not in the file's order. Null where no material has
// its name, or where several have it and differ (`ambiguous` is then set).
[[nodiscard]] const GltfMaterialFacts* facts_of(const aiMaterial& m, const GltfFacts& gltf, bool& ambiguous);

// Where each map sits in assimp, and how its texels are read: colour maps as sRGB, data maps
// linear. assimp 5.2 files the metallic-roughness map under aiTextureType_UNKNOWN and the
// occlusion map under aiTextureType_LIGHTMAP.
struct GltfMap {
    aiTextureType type;
    TexelEncoding encoding;
    std::shared_ptr<const Texture> MetallicRoughness::*slot;
    const char* what;
    TextureTransform MetallicRoughness::*transform;
};
inline const std::array<GltfMap, 5> kGltfMaps = {{
    {aiTextureType_BASE_COLOR, TexelEncoding::srgb, &MetallicRoughness::base_colour_map, "base colour",
     &MetallicRoughness::base_colour_transform},
    {aiTextureType_UNKNOWN, TexelEncoding::linear, &MetallicRoughness::metallic_roughness_map, "metallic-roughness",
     &MetallicRoughness::metallic_roughness_transform},
    {aiTextureType_NORMALS, TexelEncoding::linear, &MetallicRoughness::normal_map, "normal",
     &MetallicRoughness::normal_transform},
    {aiTextureType_LIGHTMAP, TexelEncoding::linear, &MetallicRoughness::occlusion_map, "occlusion",
     &MetallicRoughness::occlusion_transform},
    {aiTextureType_EMISSIVE, TexelEncoding::srgb, &MetallicRoughness::emissive_map, "emissive",
     &MetallicRoughness::emissive_transform},
}};

}  // namespace raster::detail
