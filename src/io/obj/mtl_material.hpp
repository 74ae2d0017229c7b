#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "io/obj/material_libraries.hpp"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <tiny_obj_loader.h>

// An MTL material made into a model part's material and maps: Blinn-Phong for a classic one,
// metallic-roughness for one that writes physically based fields (doc/conventions.md#mtl-maps,
// doc/conventions.md#mtl-pbr).
namespace raster::detail {

class MtlMaterials {
public:
    // `name` is the model's, for warnings; maps are read only when `load_maps`.
    MtlMaterials(const std::string& name, const ObjOptions& options, bool load_maps, Model& model)
        : name_(name), options_(options), load_maps_(load_maps), model_(model) {}

    // Gives `part` the material `m` of the library in `directory` describes.
    void dress(ModelPart& part, const tinyobj::material_t& m, const std::filesystem::path& directory,
               const MtlPbrFields& pbr);

private:
    using Map = std::shared_ptr<const Texture>;
    // The map file `written` names, read once however many materials name it; null, with one
    // warning saying how the material is drawn `instead`, when it cannot be read.
    Map map(const std::string& written, const std::filesystem::path& directory, const ModelPart& part,
            const std::string& instead);
    // A map built from others, built once for the same sources, of `texels` counted against the
    // model's budget; null, with a warning naming `what` for `material`, past it.
    using DerivedKey = std::tuple<const Texture*, const Texture*, char, char, float>;
    Map derived(const DerivedKey& key, std::size_t texels, const std::string& what, const std::string& material,
                const std::function<Texture()>& build);
    // The tangent-space normals of the material's bump (height) map, if it has one that reads.
    Map bump_normals(const tinyobj::material_t& m, const std::filesystem::path& directory, const ModelPart& part);
    [[nodiscard]] MetallicRoughness metallic_roughness(const ModelPart& part, const tinyobj::material_t& m,
                                                       const std::filesystem::path& directory, const MtlPbrFields& pbr);

    const std::string& name_;
    const ObjOptions& options_;
    bool load_maps_;
    Model& model_;
    std::map<std::filesystem::path, Map> loaded_;  // by canonical path
    std::map<DerivedKey, Map> derived_;
    std::size_t texels_ = 0;
};

}  // namespace raster::detail
