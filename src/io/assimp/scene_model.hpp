#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/gltf/gltf_facts.hpp"

#include <filesystem>
#include <string>
#include <vector>
#include <assimp/scene.h>

// The Model of a scene assimp read: every node's meshes placed, faces split and re-wound,
// glTF's metallic-roughness materials as Phong, their maps loaded.
namespace raster::detail {

// How a format writes vertex colours: glTF's COLOR_0 is linear; PLY, STL and every other
// format's colours are the values a screen shows, sRGB (doc/conventions.md#vertex-colours).
enum class ColourSpace { linear, srgb };

// The colour space of a format named by its ending, with or without the dot, in any letter case.
[[nodiscard]] ColourSpace colour_space_of(std::string format);

// Appends the scene's parts to `model`; `path` places the files it names and `name` is for
// messages; `gltf` is what raster read from a glTF's JSON itself, if any. Throws
// std::runtime_error naming `name` for a scene it cannot use.
void model_from_scene(const aiScene& scene, const std::filesystem::path& path, const std::string& name,
                      ColourSpace colours, const ObjOptions& options, Model& model, const GltfFacts* gltf = nullptr);

// One warning for what the scene carries and raster does not draw: skins, morph targets,
// animations, cameras, lights (doc/conventions.md#not-drawn).
// A glTF's cameras are carried in Model::cameras instead (`gltf_cameras`).
void warn_of_what_is_not_drawn(const aiScene& scene, const std::string& name, Model& model, bool gltf_cameras = false);

// One warning naming the glTF extensions among `used` that raster does not draw, if any.
void warn_of_unsupported_extensions(const std::vector<std::string>& used, const std::string& name, Model& model);

}  // namespace raster::detail
