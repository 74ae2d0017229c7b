#pragma once

#include <raster/image/colour.hpp>
#include <raster/shade/texture.hpp>
#include <raster/shade/texture_transform.hpp>

#include <memory>

// glTF 2.0's metallic-roughness material: factors in linear light, each map multiplying its
// factor (doc/conventions.md#metallic-roughness). The defaults are the specification's material
// for a primitive without one: a white metal, fully rough.
namespace raster {

struct MetallicRoughness {
    LinearRgb base_colour{1.0F, 1.0F, 1.0F};
    float metallic = 1.0F;
    float roughness = 1.0F;
    LinearRgb emissive{};  // already times KHR_materials_emissive_strength (doc/conventions.md#emissive-strength)
    float occlusion_strength = 1.0F;
    float normal_scale = 1.0F;
    // Each optional; base colour and emissive hold sRGB colour, the others linear data
    // (TexelEncoding::linear): metallic in blue, roughness in green, occlusion in red, and a
    // tangent-space normal in all three.
    std::shared_ptr<const Texture> base_colour_map{};
    std::shared_ptr<const Texture> metallic_roughness_map{};
    std::shared_ptr<const Texture> normal_map{};
    std::shared_ptr<const Texture> occlusion_map{};
    std::shared_ptr<const Texture> emissive_map{};
    // Where each map is read: KHR_texture_transform, the identity where the file gives none.
    TextureTransform base_colour_transform{};
    TextureTransform metallic_roughness_transform{};
    TextureTransform normal_transform{};
    TextureTransform occlusion_transform{};
    TextureTransform emissive_transform{};

    // The material with every factor usable: base colour, metallic, roughness and occlusion
    // strength clamped to [0, 1], emissive to [0, inf); a NaN takes the specification's default
    // (1 for the base colour, metallic, roughness and strengths, 0 for emissive); a normal scale
    // that is not finite takes 1.
    [[nodiscard]] MetallicRoughness usable() const noexcept;
};

}  // namespace raster
