// OBJ models read by raster's own reader, their materials by tinyobjloader's MTL reader (only this folder
// includes it); stays whole as the one path from text to parts.
#include <raster/io/obj_file.hpp>

#include "io/for_each_index.hpp"
#include "io/model_builder.hpp"
#include "io/obj/material_libraries.hpp"
#include "io/obj/mtl_material.hpp"
#include "io/obj/obj_pieces.hpp"
#include "io/obj_survey.hpp"
#include "io/obj_text.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>
#include <tiny_obj_loader.h>

namespace raster {

using detail::MaterialLibraries;
using detail::MtlMaterials;
using detail::rethrow_named;
using detail::text_rules;

namespace {

// A problem that stops the model: the caller prefixes the file's name.
struct BadModel : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What the pieces found besides geometry, with the warnings that say it once per cause.
detail::ObjSurvey survey_of(const std::vector<detail::ObjPiece>& pieces, const std::string& name) {
    detail::ObjSurvey survey;
    std::size_t empty_library_line = 0, empty_libraries = 0;
    std::array<const detail::BadNumber*, 3> first_bad{};
    std::array<std::size_t, 3> bad{};
    for (const detail::ObjPiece& piece : pieces) {
        for (std::size_t k = 0; k < 3; ++k) {
            survey.defined[k] += piece.counts.defined[k];
            if (first_bad[k] == nullptr && !piece.bad[k].empty()) first_bad[k] = &piece.bad[k].front();
            bad[k] += piece.bad[k].size();
        }
        survey.faces += piece.faces;
        survey.skipped_faces += piece.skipped_faces;
        survey.points += piece.points.size();
        survey.segments += piece.segment_count;
        survey.coloured_vertices += piece.coloured_vertices;
        if (survey.short_line == 0) survey.short_line = piece.short_line;
        if (empty_libraries == 0) empty_library_line = piece.empty_library_line;
        empty_libraries += piece.empty_libraries;
        for (const detail::MaterialStatement& statement : piece.materials) {
            if (statement.library) {
                for (const std::string& library : statement.names)
                    survey.library_lines.emplace(library, statement.line);
            } else if (!statement.names.empty() &&
                       survey.material_lines.emplace(statement.names[0], statement.line).second) {
                survey.materials.push_back({statement.names[0], statement.line});
            }
        }
    }
    if (empty_libraries > 0) {
        survey.warnings.push_back(
            name + ":" + std::to_string(empty_library_line) + ": mtllib names no file" +
            (empty_libraries > 1 ? " (nor do " + std::to_string(empty_libraries - 1) + " more mtllib lines)" : ""));
    }
    if (survey.short_line != 0)
        survey.warnings.push_back(name + ":" + std::to_string(survey.short_line) +
                                  ": a line (l) of fewer than 2 vertices draws nothing; skipped");
    for (std::size_t k = 0; k < 3; ++k) {
        if (first_bad[k] == nullptr) continue;  // a face using one would have thrown
        const std::size_t more = bad[k] - 1;
        survey.warnings.push_back(
            name + ":" + std::to_string(first_bad[k]->line) + ": " + detail::kObjKindNames[k] + " " +
            std::to_string(first_bad[k]->index + 1) + " has " + first_bad[k]->problem + "; no face uses it" +
            (more > 0 ? " (nor " + std::to_string(more) + " more such " + detail::kObjKindPlurals[k] + ")" : ""));
    }
    return survey;
}

// The material in force at each usemtl, libraries read as their mtllib lines come, in file order.
std::vector<detail::PieceMaterials> materials_in_force(const std::vector<detail::ObjPiece>& pieces,
                                                       MaterialLibraries& libraries,
                                                       std::vector<tinyobj::material_t>& materials) {
    std::map<std::string, int> ids;
    std::set<std::string> read;
    std::vector<detail::PieceMaterials> in_force(pieces.size());
    int current = -1;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        in_force[i].entering = current;
        for (const detail::MaterialStatement& statement : pieces[i].materials) {
            if (!statement.library) {
                // A usemtl without a name picks a material without one (a bare newmtl), as tinyobjloader did.
                const auto found = ids.find(statement.names.empty() ? std::string() : statement.names[0]);
                current = found == ids.end() ? -1 : found->second;
                in_force[i].by_statement.push_back(current);
                continue;
            }
            in_force[i].by_statement.push_back(-1);
            // The first of the named libraries that reads, as tinyobjloader takes them.
            for (const std::string& library : statement.names) {
                if (read.contains(library)) continue;
                if (libraries(library, &materials, &ids, nullptr, nullptr)) {
                    read.insert(library);
                    break;
                }
            }
        }
    }
    return in_force;
}

// The text's pieces: each holds its own values, so the text may go once they are read.
std::vector<detail::ObjPiece> pieces_of(std::string_view text, const std::string& name, const ObjOptions& options) {
    return detail::read_obj_pieces(text, name, kMaxFaceCorners, options.max_line_bytes,
                                   detail::threads_or_cores(options.threads), options.range_bytes);
}

Model model_from(std::vector<detail::ObjPiece> pieces, const std::string& name, const std::filesystem::path& directory,
                 std::optional<std::string_view> mtl, const ObjOptions& options, bool load_maps) {
    const std::size_t threads = detail::threads_or_cores(options.threads);
    const detail::ObjSurvey survey = survey_of(pieces, name);
    MaterialLibraries libraries(directory, mtl, name, survey, options);
    std::vector<tinyobj::material_t> materials;
    const std::vector<detail::PieceMaterials> in_force = materials_in_force(pieces, libraries, materials);
    Model model;
    model.warnings = survey.warnings;
    for (std::string& warning : libraries.warnings()) model.warnings.push_back(std::move(warning));
    detail::warn_of_missing_materials(model.warnings, name, survey, materials, libraries.any_failed());
    model.sources = std::move(libraries.sources());
    detail::PolygonSoup soup = detail::join_obj_pieces(pieces, in_force, threads);
    if (survey.skipped_faces > 0) {
        model.warnings.push_back(name + ": skipped " + std::to_string(survey.skipped_faces) +
                                 " faces with fewer than 3 corners");
    }
    if (survey.coloured_vertices > 0 && soup.colours.empty()) {
        model.warnings.push_back(name + ": " + std::to_string(survey.coloured_vertices) + " of " +
                                 std::to_string(survey.defined[0]) +
                                 " vertices give a colour, and OBJ's colours are all or none; drawing none");
    }
    if (survey.faces == 0 && survey.skipped_faces == 0 && survey.points == 0 && survey.segments == 0 &&
        survey.short_line == 0) {
        // A normal that is not a number (warned of) lights no point: zero, as a point without one.
        for (glm::vec3& normal : soup.normals) normal = std::isnan(normal.x) ? glm::vec3(0.0F) : normal;
        detail::add_every_vertex_as_a_point(soup);  // a point cloud, as MeshLab writes one
    }
    MtlMaterials dresser(name, options, load_maps, model);
    for (auto& [id, mesh] : detail::meshes_by_material(soup, options.crease_degrees, threads)) {
        ModelPart part{"", std::move(mesh), default_model_material()};
        if (id >= 0 && static_cast<std::size_t>(id) < materials.size()) {
            const auto index = static_cast<std::size_t>(id);
            dresser.dress(part, materials[index], libraries.directory_of(index),
                          libraries.pbr_fields(materials[index].name));
        }
        model.parts.push_back(std::move(part));
    }
    // One line per distinct warning, however often the file repeats its cause.
    std::vector<std::string> distinct;
    std::unordered_set<std::string> seen;
    for (std::string& warning : model.warnings) {
        if (seen.insert(warning).second) distinct.push_back(std::move(warning));
    }
    model.warnings = std::move(distinct);
    if (model.parts.empty() && !soup.triangles.empty()) {
        float farthest = 0.0F;
        for (const glm::vec3& p : soup.positions)
            farthest = std::max({farthest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        // 32-bit floats keep about 7 digits: far from the origin, a small face collapses to a line.
        char hint[160] = "";
        if (farthest >= 65536.0F) {
            std::snprintf(
                hint, sizeof hint,
                " (stored as 32-bit floats, coordinates near %.0e step by %g: move the model nearer the origin)",
                static_cast<double>(farthest), static_cast<double>(std::nextafter(farthest, HUGE_VALF) - farthest));
        }
        throw BadModel(std::string("every face has no area") + hint);
    }
    if (model.parts.empty()) throw BadModel(kNothingToDraw);
    return model;
}

}  // namespace

Model read_obj(const std::filesystem::path& path, const ObjOptions& options) {
    const std::string name = printable(path.string());
    try {
        InputFile file(path, text_rules("model", "a Wavefront OBJ text file", options.confine));
        std::vector<detail::ObjPiece> pieces;
        {
            const std::vector<std::uint8_t> bytes = file.read_all();
            pieces = pieces_of({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, name, options);
        }
        Model model =
            model_from(std::move(pieces), name, path.parent_path(), std::nullopt, options, options.load_textures);
        model.sources.insert(model.sources.begin(), file.record());
        return model;
    } catch (const std::runtime_error&) {
        rethrow_named(name);
    }
}

Model parse_obj(std::string_view obj, std::string_view mtl, ObjOptions options) {
    const std::string name = "<memory>";
    try {
        return model_from(pieces_of(obj, name, options), name, ".", mtl, options, false);
    } catch (const std::runtime_error&) {
        rethrow_named(name);
    }
}

}  // namespace raster
