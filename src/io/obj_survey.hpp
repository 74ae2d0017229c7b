#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

// What reading an OBJ file found out besides its geometry: the counts its warnings quote, and the
// material libraries and materials it names, with the lines that name them.
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
    std::array<std::size_t, 3> defined{};                         // v, vt and vn statements
    std::size_t skipped_faces = 0;                                // faces of fewer than 3 corners
    std::size_t faces = 0;                                        // of 3 corners or more
    std::size_t points = 0;                                       // vertices named by p statements
    std::size_t segments = 0;           // pairs of vertices one after the other in l statements
    std::size_t short_line = 0;         // the first l line of fewer than 2 vertices, or 0
    std::size_t coloured_vertices = 0;  // v statements giving a colour after x y z
};

}  // namespace raster::detail
