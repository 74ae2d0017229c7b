#pragma once

#include "io/model_builder.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

// One byte range of an OBJ file read on its own, so that ranges are read on several cores: what
// its lines define and draw, every index resolved against the counts of the ranges before it.
namespace raster::detail {

// v, vt and vn: what a corner names, in the order of the corner's fields.
enum ObjKind : std::size_t { kObjPosition, kObjUv, kObjNormal };
inline constexpr std::array<const char*, 3> kObjKindNames = {"vertex", "texture coordinate", "normal"};
inline constexpr std::array<const char*, 3> kObjKindPlurals = {"vertices", "texture coordinates", "normals"};

// How many lines, and v, vt and vn statements, a range holds (or all the ranges before one).
struct ObjCounts {
    std::array<std::size_t, 3> defined{};
    std::size_t lines = 0;
};

// A coordinate that is not the number it should be: which (counted over the whole file), the
// line (in the file), and why. Its value is stored as NaN, so a use of it is found where it is.
struct BadNumber {
    std::size_t index;
    std::size_t line;
    std::string problem;
};
using BadNumbers = std::array<std::vector<BadNumber>, 3>;

// mtllib or usemtl, in file order: materials are looked up as the libraries before them define them.
struct MaterialStatement {
    bool library;                    // mtllib; else usemtl
    std::vector<std::string> names;  // mtllib: the files; usemtl: the material, none for the default
    std::size_t line;                // in the file
};

// A corner as the file gives it: indices from 0 over the whole file; kNoIndex where it names none.
struct ObjCorner {
    std::uint32_t position = 0;
    std::uint32_t uv = kNoIndex;
    std::uint32_t normal = kNoIndex;
};

// A triangle of corners clockwise; its material is the ordinal of the piece's usemtl in force,
// or -1 for the one in force where the piece starts.
struct ObjTriangle {
    std::array<ObjCorner, 3> corners;
    int material;
};

// A face of four or more corners: its n - 2 triangles are held in place until every position is known.
struct HeldPolygon {
    std::size_t first_triangle;
    std::size_t first_corner;  // in ObjPiece::polygon_corners
    std::size_t corners;
};

struct ObjPiece {
    ObjCounts counts;                  // of this range
    std::vector<glm::vec3> positions;  // mirrored into raster's world, like the normals
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;
    std::vector<LinearRgb> colours;  // while every v so far gives one
    std::size_t coloured_vertices = 0;
    BadNumbers bad;
    std::vector<ObjTriangle> triangles;
    std::vector<ObjCorner> polygon_corners;
    std::vector<HeldPolygon> polygons;
    std::vector<ObjCorner> points;
    std::vector<std::array<ObjCorner, 2>> segments;
    std::vector<MaterialStatement> materials;
    std::size_t faces = 0, skipped_faces = 0, segment_count = 0;
    std::size_t short_line = 0;  // the first l of fewer than 2 vertices, or 0
    std::size_t empty_library_line = 0, empty_libraries = 0;
    // Whether a corner names a v, vt or vn of an earlier range, to be checked once they are read.
    bool names_earlier = false;
};

// Where a range starts in its file, and what the earlier ranges hold.
struct ObjRange {
    std::string_view text;
    ObjCounts before;
    bool first = true;  // a UTF-8 byte order mark may open it
};

// The lines, and v, vt and vn statements, of a range: cheap, so every range knows its indices.
[[nodiscard]] ObjCounts count_obj_range(std::string_view text, bool first);

// Reads a range. Throws std::runtime_error "NAME:LINE: ..." for the first problem in it. With
// `earlier_bad` (the bad numbers of every range before, or of all ranges), a use of one of them
// throws too, and the range is only checked: what it draws is not kept.
[[nodiscard]] ObjPiece read_obj_range(const ObjRange& range, const std::string& name, std::size_t max_corners,
                                      std::size_t max_line_bytes, const BadNumbers* earlier_bad = nullptr);

}  // namespace raster::detail
