// OBJ models through tinyobjloader, which only this folder includes; stays whole as the one path from text to parts.
#include <raster/io/obj_file.hpp>

#include "geometry/polygon_triangles.hpp"
#include "io/input_stream.hpp"
#include "io/model_builder.hpp"
#include "io/obj/material_libraries.hpp"
#include "io/obj/mtl_material.hpp"
#include "io/obj_survey.hpp"
#include "io/obj_text.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>
#include <tiny_obj_loader.h>

namespace raster {

using detail::load_failure;
using detail::MaterialLibraries;
using detail::MtlMaterials;
using detail::rethrow_named;
using detail::text_rules;

namespace {

// A problem that stops the model: the caller prefixes the file's name.
struct BadModel : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Checks one index of a face corner, point or line vertex against the count of what it names.
std::int64_t checked(int index, std::size_t count, const char* what, const char* statement, std::size_t number,
                     bool optional) {
    if (index < 0 && optional) return detail::kNoIndex;
    if (index < 0 || static_cast<std::size_t>(index) >= count) {
        throw BadModel(std::string(statement) + " " + std::to_string(number) + " names " + what + " " +
                       std::to_string(index + 1) + ", but the file has " + std::to_string(count));
    }
    return index;
}

// An OBJ colour channel (sRGB, as MeshLab and others write it) in linear light, clamped to
// [0, 1], white where it is not a number (doc/conventions.md#vertex-colours).
float linear_obj_channel(tinyobj::real_t written) {
    const float c = std::isfinite(written) ? std::clamp(static_cast<float>(written), 0.0F, 1.0F) : 1.0F;
    return static_cast<float>(linear_from_srgb_channel(c));
}

// Positions and normals mirrored into raster's left-handed world; each face split into exactly
// its own area and every piece re-wound to match.
detail::PolygonSoup soup_from(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                              const detail::ObjSurvey& survey, std::size_t& skipped) {
    detail::PolygonSoup soup;
    for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
        soup.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], -attrib.vertices[i + 2]);
    }
    for (std::size_t i = 0; i + 2 < attrib.normals.size(); i += 3) {
        soup.normals.emplace_back(attrib.normals[i], attrib.normals[i + 1], -attrib.normals[i + 2]);
    }
    for (std::size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2)
        soup.uvs.emplace_back(attrib.texcoords[i], attrib.texcoords[i + 1]);
    // tinyobjloader keeps colours only when every v gives them (doc/conventions.md#vertex-colours).
    const bool coloured = attrib.colors.size() == attrib.vertices.size();
    if (coloured) {
        for (std::size_t i = 0; i + 2 < attrib.colors.size(); i += 3) {
            soup.colours.push_back({linear_obj_channel(attrib.colors[i]), linear_obj_channel(attrib.colors[i + 1]),
                                    linear_obj_channel(attrib.colors[i + 2])});
        }
    }
    std::size_t point = 0, line = 0;
    const auto corner_of = [&](const tinyobj::index_t& index, const char* statement, std::size_t number) {
        const detail::SoupCorner corner{
            checked(index.vertex_index, soup.positions.size(), "vertex", statement, number, false),
            checked(index.normal_index, soup.normals.size(), "normal", statement, number, true),
            checked(index.texcoord_index, soup.uvs.size(), "texture coordinate", statement, number, true),
            coloured ? checked(index.vertex_index, soup.colours.size(), "colour", statement, number, false)
                     : detail::kNoIndex};
        const glm::vec3& p = soup.positions[static_cast<std::size_t>(corner.position)];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {  // the survey refuses these first
            throw BadModel("vertex " + std::to_string(corner.position + 1) + " is not a finite point");
        }
        return corner;
    };
    std::size_t face = 0;
    auto large = survey.large_faces.begin();
    std::vector<detail::SoupCorner> corners;
    std::vector<glm::dvec3> outline;
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
            std::size_t count = shape.mesh.num_face_vertices[f];
            if (large != survey.large_faces.end() && large->first == face)
                count = (large++)->second;  // the survey counted them whole
            const std::size_t first = next;
            next += count;
            if (next > shape.mesh.indices.size()) throw BadModel("face " + std::to_string(face + 1) + " is cut short");
            if (count < 3) {  // tinyobjloader drops these itself; kept as a guard
                ++skipped;
                continue;
            }
            corners.clear();
            outline.clear();
            for (std::size_t k = first; k < next; ++k) {
                corners.push_back(corner_of(shape.mesh.indices[k], "face", face + 1));
                outline.emplace_back(soup.positions[static_cast<std::size_t>(corners.back().position)]);
            }
            const int material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
            // Each piece turned from OBJ's counter-clockwise to raster's clockwise order.
            for (const auto& [a, b, c] : detail::triangles_of_polygon(outline)) {
                soup.triangles.push_back({{corners[a], corners[c], corners[b]}, material});
            }
        }
        if (next != shape.mesh.indices.size()) throw BadModel("its faces and their corners do not line up");
        // OBJ gives points and lines no material: they take the default (doc/conventions.md#points-and-lines).
        for (const tinyobj::index_t& index : shape.points.indices)
            soup.points.push_back({corner_of(index, "point", ++point), -1});
        std::size_t at = 0;
        for (const int count : shape.lines.num_line_vertices) {
            ++line;
            if (count < 0 || static_cast<std::size_t>(count) > shape.lines.indices.size() - at)
                throw BadModel("line " + std::to_string(line) + " is cut short");
            for (std::size_t k = at; k + 1 < at + static_cast<std::size_t>(count); ++k) {
                soup.segments.push_back({{corner_of(shape.lines.indices[k], "line", line),
                                          corner_of(shape.lines.indices[k + 1], "line", line)},
                                         -1});
            }
            at += static_cast<std::size_t>(count);
        }
    }
    if (survey.faces == 0 && survey.skipped_faces == 0 && survey.points == 0 && survey.segments == 0 &&
        survey.short_line == 0) {
        detail::add_every_vertex_as_a_point(soup);  // a point cloud, as MeshLab writes one
    }
    return soup;
}

// tinyobjloader must have read the statements the survey checked, no more and no fewer: a
// disagreement would leave a number unchecked.
void check_same_reading(const tinyobj::attrib_t& attrib, const detail::ObjSurvey& survey) {
    const std::array<std::size_t, 3> read = {attrib.vertices.size() / 3, attrib.texcoords.size() / 2,
                                             attrib.normals.size() / 3};
    if (read != survey.defined) {
        throw std::runtime_error("the file's v, vt and vn lines were counted as " + std::to_string(survey.defined[0]) +
                                 ", " + std::to_string(survey.defined[1]) + " and " +
                                 std::to_string(survey.defined[2]) + " by one reading and " + std::to_string(read[0]) +
                                 ", " + std::to_string(read[1]) + " and " + std::to_string(read[2]) +
                                 " by the other; please report this file");
    }
}

Model model_from(std::istream& obj, const std::string& name, const detail::ObjSurvey& survey,
                 MaterialLibraries& libraries, const ObjOptions& options, bool load_maps) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string ignored_warnings, err;  // the survey has said what matters, in raster's words
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &ignored_warnings, &err, &obj, &libraries, false, false)) {
        throw load_failure(err, name);
    }
    check_same_reading(attrib, survey);
    Model model;
    model.warnings = survey.warnings;
    for (std::string& warning : libraries.warnings()) model.warnings.push_back(std::move(warning));
    detail::warn_of_missing_materials(model.warnings, name, survey, materials, libraries.any_failed());
    model.sources = std::move(libraries.sources());
    std::size_t skipped = survey.skipped_faces;
    std::size_t dropped_again = 0;
    const detail::PolygonSoup soup = soup_from(attrib, shapes, survey, dropped_again);
    skipped = std::max(skipped, dropped_again);
    if (skipped > 0)
        model.warnings.push_back(name + ": skipped " + std::to_string(skipped) + " faces with fewer than 3 corners");
    if (survey.coloured_vertices > 0 && soup.colours.empty()) {
        model.warnings.push_back(name + ": " + std::to_string(survey.coloured_vertices) + " of " +
                                 std::to_string(survey.defined[0]) +
                                 " vertices give a colour, and OBJ's colours are all or none; drawing none");
    }
    MtlMaterials dresser(name, options, load_maps, model);
    for (auto& [id, mesh] : detail::meshes_by_material(soup, options.crease_degrees)) {
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
        const detail::ObjSurvey survey = detail::survey_obj(name, kMaxFaceCorners, [&](const auto& visit) {
            for_each_line(file, name, options.max_line_bytes, visit);
        });
        detail::InputStreamBuf buffer(file);
        std::istream in(&buffer);
        MaterialLibraries libraries(path.parent_path(), std::nullopt, name, survey, options);
        Model model = model_from(in, name, survey, libraries, options, options.load_textures);
        model.sources.insert(model.sources.begin(), file.record());
        return model;
    } catch (const std::runtime_error&) {
        rethrow_named(name);
    }
}

Model parse_obj(std::string_view obj, std::string_view mtl, ObjOptions options) {
    const std::string name = "<memory>";
    try {
        if (obj.starts_with("\xEF\xBB\xBF")) obj.remove_prefix(3);  // a UTF-8 byte order mark, as a file's is skipped
        const detail::ObjSurvey survey = detail::survey_obj(
            name, kMaxFaceCorners, [&](const auto& visit) { for_each_line(obj, name, options.max_line_bytes, visit); });
        std::istringstream in{std::string(obj)};
        MaterialLibraries libraries(".", mtl, name, survey, options);
        return model_from(in, name, survey, libraries, options, false);
    } catch (const std::runtime_error&) {
        rethrow_named(name);
    }
}

}  // namespace raster
