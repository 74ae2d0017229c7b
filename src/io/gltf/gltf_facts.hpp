#pragma once

#include <raster/io/model_camera.hpp>
#include <raster/shade/texture_transform.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

// What raster reads from a glTF file's JSON itself, beyond what assimp 5.2 hands on: the
// extensions it names, its materials' KHR_texture_transform and KHR_materials_emissive_strength,
// and its cameras placed by their nodes (doc/conventions.md#texture-transform,
// doc/conventions.md#emissive-strength, doc/conventions.md#model-cameras).
namespace raster::detail {

// The five maps of a metallic-roughness material, in this order everywhere.
inline constexpr std::array<const char*, 5> kGltfMapNames{"base colour", "metallic-roughness", "normal", "occlusion",
                                                          "emissive"};

struct GltfMaterialFacts {
    std::string name;  // "" when it has none
    std::array<TextureTransform, 5> transforms{};
    // The texture coordinate set each map reads: its texCoord, or its transform's.
    std::array<std::uint64_t, 5> coordinate_sets{};
    std::optional<double> emissive_strength;  // as written
    // Fields read otherwise than written, each the end of a sentence about the material.
    std::vector<std::string> problems;
    friend bool operator==(const GltfMaterialFacts&, const GltfMaterialFacts&) = default;
};

struct GltfFacts {
    std::vector<std::string> extensions;  // extensionsUsed and extensionsRequired, once each
    std::vector<GltfMaterialFacts> materials;
    std::vector<ModelCamera> cameras;
    // Fields of the cameras read otherwise than written, each a sentence end ("camera 1's yfov ...").
    std::vector<std::string> camera_problems;
};

}  // namespace raster::detail
