#pragma once

#include <raster/io/input_file.hpp>
#include <raster/io/obj_file.hpp>

#include "io/obj_survey.hpp"

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <tiny_obj_loader.h>

// The MTL files an OBJ names, read for tinyobjloader from beside the OBJ (or from text given in
// memory), remembering which directory every material came from, for its texture paths.
namespace raster::detail {

// Which physically based fields an MTL material writes (doc/conventions.md#mtl-pbr): tinyobjloader
// reads their values but not whether they were there.
struct MtlPbrFields {
    bool roughness = false;      // Pr
    bool metallic = false;       // Pm
    bool roughness_map = false;  // map_Pr
    bool metallic_map = false;   // map_Pm
    bool normal_map = false;     // norm
    [[nodiscard]] bool any() const noexcept {
        return roughness || metallic || roughness_map || metallic_map || normal_map;
    }
};

class MaterialLibraries final : public tinyobj::MaterialReader {
public:
    MaterialLibraries(std::filesystem::path directory, std::optional<std::string_view> text, std::string obj_name,
                      const ObjSurvey& survey, const ObjOptions& options)
        : directory_(std::move(directory)), text_(text), obj_name_(std::move(obj_name)), survey_(survey),
          options_(options) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string*, std::string*) override;

    [[nodiscard]] const std::filesystem::path& directory_of(std::size_t material) const {
        return directories_.at(material);
    }
    // At most one warning, however many libraries failed.
    [[nodiscard]] std::vector<std::string> warnings() const;
    [[nodiscard]] std::vector<InputRecord>& sources() noexcept { return sources_; }
    [[nodiscard]] bool any_failed() const noexcept { return failures_ > 0; }
    // The physically based fields the material of that name writes, in any library read.
    [[nodiscard]] MtlPbrFields pbr_fields(const std::string& material) const;

private:
    std::filesystem::path directory_;
    std::optional<std::string_view> text_;
    std::string obj_name_;
    const ObjSurvey& survey_;
    const ObjOptions& options_;
    std::vector<std::filesystem::path> directories_;
    std::string first_failure_;
    std::size_t failures_ = 0;
    std::vector<InputRecord> sources_;
    std::map<std::string, MtlPbrFields> pbr_fields_;
    std::string reading_;  // the material the library's lines describe now

    void note_fields(std::string_view line);
};

// The survey's word on materials a face asks for that no library gave, unless a library that
// failed already explains it: one warning for one fact.
void warn_of_missing_materials(std::vector<std::string>& warnings, const std::string& name, const ObjSurvey& survey,
                               const std::vector<tinyobj::material_t>& materials, bool a_library_failed);

}  // namespace raster::detail
