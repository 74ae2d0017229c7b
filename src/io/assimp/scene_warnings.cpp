#include "io/assimp/scene_model.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace raster::detail {

// One warning for what the scene carries and raster does not draw (doc/conventions.md#not-drawn).
void warn_of_what_is_not_drawn(const aiScene& scene, const std::string& name, Model& model, bool gltf_cameras) {
    bool skinned = false, morphed = false;
    for (unsigned i = 0; scene.mMeshes != nullptr && i < scene.mNumMeshes; ++i) {
        if (scene.mMeshes[i] == nullptr) continue;
        skinned = skinned || scene.mMeshes[i]->mNumBones > 0;
        morphed = morphed || scene.mMeshes[i]->mNumAnimMeshes > 0;
    }
    std::vector<std::string> parts;
    if (skinned) parts.emplace_back("a skin (drawn in its rest pose)");
    if (morphed) parts.emplace_back("morph targets (drawn in the rest pose)");
    const auto counted = [&](unsigned count, const char* one, const char* many) {
        if (count > 0) parts.push_back(std::to_string(count) + " " + (count == 1 ? one : many));
    };
    counted(scene.mNumAnimations, "animation (not played)", "animations (not played)");
    counted(gltf_cameras ? 0U : scene.mNumCameras, "camera (raster frames the model itself)",
            "cameras (raster frames the model itself)");
    counted(scene.mNumLights, "light (raster lights the model itself)", "lights (raster lights the model itself)");
    if (parts.empty()) return;
    std::string text;
    for (std::size_t i = 0; i < parts.size(); ++i)
        text += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    model.warnings.push_back(name + ": it carries " + text);
}

void warn_of_unsupported_extensions(const std::vector<std::string>& used, const std::string& name, Model& model) {
    // Drawn by raster's materials (doc/conventions.md#not-drawn).
    static constexpr std::array<std::string_view, 2> kDrawn{"KHR_texture_transform", "KHR_materials_emissive_strength"};
    std::string names;
    for (const std::string& extension : used) {
        if (std::find(kDrawn.begin(), kDrawn.end(), extension) != kDrawn.end()) continue;
        names += (names.empty() ? "" : ", ") + printable(extension, 64);
    }
    if (!names.empty())
        model.warnings.push_back(name + ": glTF extensions raster does not draw: " + names + "; drawn without them");
}

}  // namespace raster::detail
