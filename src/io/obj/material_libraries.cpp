#include "io/obj/material_libraries.hpp"

#include "io/input_stream.hpp"
#include "io/named_path.hpp"
#include "io/obj_text.hpp"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_set>

namespace raster::detail {

bool MaterialLibraries::operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                                   std::map<std::string, int>* names, std::string*, std::string*) {
    const std::filesystem::path path =
        text_ ? directory_ / name : resolve_named_path(directory_, name, options_.confine);
    std::string ignored_warnings, ignored_errors;  // LoadMtl's only warning is about d and Tr, both read anyway
    if (text_) {
        // Text in memory is already held whole: no line cap.
        for_each_line(*text_, obj_name_, std::numeric_limits<std::size_t>::max(),
                      [&](std::string_view line, std::size_t) { note_fields(line); });
        std::istringstream in{std::string(*text_)};
        tinyobj::LoadMtl(names, materials, &in, &ignored_warnings, &ignored_errors);
    } else {
        note_named(sources_, path, "material library");
        try {
            InputFile file(path, text_rules("material library", "an MTL text file", options_.confine));
            const std::string shown = printable(path.string());
            for_each_line(file, shown, options_.max_line_bytes,
                          [&](std::string_view line, std::size_t) { note_fields(line); });
            InputStreamBuf buffer(file);
            std::istream in(&buffer);
            tinyobj::LoadMtl(names, materials, &in, &ignored_warnings, &ignored_errors);
        } catch (const std::runtime_error& problem) {
            if (failures_++ > 0) return false;  // one warning for the first; the count for the rest
            const auto line = survey_.library_lines.find(name);
            const std::string at =
                obj_name_ + (line != survey_.library_lines.end() ? ":" + std::to_string(line->second) : "") + ": ";
            const std::string what = problem.what(), shown = printable(path.string());
            // A line-cap refusal already names the library and its line.
            first_failure_ = at + (what.starts_with(shown + ":") ? what : "material library '" + shown + "' " + what);
            return false;
        }
    }
    directories_.resize(materials->size(), path.parent_path());
    return true;
}

MtlPbrFields MaterialLibraries::pbr_fields(const std::string& material) const {
    const auto found = pbr_fields_.find(material);
    return found == pbr_fields_.end() ? MtlPbrFields{} : found->second;
}

// Keywords as tinyobjloader takes them: after any spaces and tabs, and followed by one.
void MaterialLibraries::note_fields(std::string_view line) {
    line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
    const auto keyword = [&](std::string_view word) {
        return line.starts_with(word) && line.size() > word.size() &&
               (line[word.size()] == ' ' || line[word.size()] == '\t');
    };
    if (keyword("newmtl")) {
        reading_ = std::string(line.substr(7, line.find_last_not_of(" \t") + 1 - 7));  // tinyobjloader's name
        return;
    }
    MtlPbrFields& fields = pbr_fields_[reading_];
    fields.roughness |= keyword("Pr");
    fields.metallic |= keyword("Pm");
    fields.roughness_map |= keyword("map_Pr");
    fields.metallic_map |= keyword("map_Pm");
    fields.normal_map |= keyword("norm");
}

std::vector<std::string> MaterialLibraries::warnings() const {
    if (failures_ == 0) return {};
    const std::string more =
        failures_ > 1 ? " (and " + std::to_string(failures_ - 1) + " more material libraries)" : "";
    return {first_failure_ + more + "; drawing the default material"};
}

void warn_of_missing_materials(std::vector<std::string>& warnings, const std::string& name, const ObjSurvey& survey,
                               const std::vector<tinyobj::material_t>& materials, bool a_library_failed) {
    if (a_library_failed) return;
    std::unordered_set<std::string_view> defined;
    for (const tinyobj::material_t& m : materials) defined.insert(m.name);
    const NamedAt* first = nullptr;
    std::size_t missing = 0;
    for (const NamedAt& used : survey.materials) {
        if (defined.contains(used.name)) continue;
        if (missing++ == 0) first = &used;
    }
    if (first == nullptr) return;
    const std::string more =
        missing > 1 ? " (nor " + std::to_string(missing - 1) + " more materials the faces use)" : "";
    warnings.push_back(name + ":" + std::to_string(first->line) + ": material '" + printable(first->name, 80) + "' " +
                       (survey.library_lines.empty() ? "is used, but the file names no material library"
                                                     : "is in none of the file's material libraries") +
                       more + "; drawing the default material");
}

}  // namespace raster::detail
