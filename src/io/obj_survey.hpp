#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

// The first of two readings of an OBJ file: every line checked in raster's own words before
// tinyobjloader builds the model, which reads numbers it cannot parse as 0 and drops what it
// cannot use with messages of its own.
namespace raster::detail {

// Where the file names something, for warnings about it.
struct NamedAt {
    std::string name;
    std::size_t line;
};

struct ObjSurvey {
    std::vector<std::string> warnings;                            // each "FILE:LINE: ...", at most one per cause
    std::unordered_map<std::string, std::size_t> library_lines;   // mtllib names, first line of each
    std::unordered_map<std::string, std::size_t> material_lines;  // usemtl names, first line of each
    std::vector<NamedAt> materials;                               // usemtl names in order of first use
    std::array<std::size_t, 3> defined{};  // v, vt and vn statements, as tinyobjloader counts them
    std::size_t skipped_faces = 0;         // faces of fewer than 3 corners
    // Faces of 256 corners or more, as (index among faces of 3 or more, corners): tinyobjloader
    // keeps a face's corner count in one byte, so these are the counts it gets wrong.
    std::vector<std::pair<std::size_t, std::size_t>> large_faces;
    std::size_t faces = 0;              // of 3 corners or more
    std::size_t points = 0;             // vertices named by p statements
    std::size_t segments = 0;           // pairs of vertices one after the other in l statements
    std::size_t short_line = 0;         // the first l line of fewer than 2 vertices, or 0
    std::size_t coloured_vertices = 0;  // v statements giving a colour after x y z
};

// Checks one OBJ text line by line (`lines` calls its visitor with each line and its number):
// faces, points (p) and lines (l) must name, by v, v/vt, v/vt/vn or v//vn, only finite
// coordinates defined before them; faces have at most `max_corners` corners. Throws std::runtime_error "NAME:LINE: ..."
// otherwise.
[[nodiscard]] ObjSurvey survey_obj(
    const std::string& name, std::size_t max_corners,
    const std::function<void(const std::function<void(std::string_view, std::size_t)>&)>& lines);

}  // namespace raster::detail
