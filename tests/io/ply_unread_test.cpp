// What a PLY carries that raster does not draw is named, once per file, whichever reader reads it
// (doc/conventions.md#ply-reader).
#include <raster/io/model.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/ply_file.hpp>

#include "support/ply_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using raster::Model;
using test_support::PlySpec;

namespace {

Model parsed(const std::string& text) { return raster::parse_ply(std::vector<std::uint8_t>(text.begin(), text.end())); }

// A triangle of `vertex_extra` more vertex properties (ASCII header lines) and `face_extra` face
// properties before the corners, with `elements` (header and body) after the faces.
std::string triangle(const std::string& vertex_extra, const std::string& vertex_values, const std::string& face_extra,
                     const std::string& face_values, const std::string& elements = "",
                     const std::string& element_rows = "") {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" +
           vertex_extra + "element face 1\n" + face_extra + "property list uchar int vertex_indices\n" + elements +
           "end_header\n0 0 0 " + vertex_values + "\n1 0 0 " + vertex_values + "\n0 1 0 " + vertex_values + "\n" +
           face_values + "3 0 1 2\n" + element_rows;
}

}  // namespace

TEST(PlyUnread, VertexPropertiesItDoesNotDrawAreNamedInOneWarningInEveryEncoding) {
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        PlySpec spec;
        spec.format = format;
        spec.vertex = {{"float", "x"},       {"float", "y"},          {"float", "z"},
                       {"float", "quality"}, {"ushort", "intensity"}, {"uchar", "red"},
                       {"uchar", "green"},   {"uchar", "blue"},       {"double", "scalar_Confidence"}};
        spec.vertices = {{0, 0, 0, 0.5, 300, 255, 0, 0, 0.25}, {1, 2, 3, 0.75, 400, 0, 255, 0, 0.5}};
        spec.face_list = "";
        const Model model = parsed(test_support::ply_text(spec));
        ASSERT_EQ(model.parts.size(), 1U) << format;
        EXPECT_EQ(model.parts[0].mesh.colours.size(), 2U) << format;
        EXPECT_EQ(model.warnings, std::vector<std::string>{"<memory>: vertex properties quality, intensity, "
                                                           "scalar_Confidence are not drawn"})
            << format;
    }
    const Model one = parsed(triangle("property float radius\n", "0.5", "", ""));
    EXPECT_EQ(one.warnings, std::vector<std::string>{"<memory>: vertex property radius is not drawn"});
}

TEST(PlyUnread, FacePropertiesAndOtherElementsAreNamedOnceEachAndEmptyOnesNot) {
    const Model model = parsed(triangle("property list uchar float normals_list\n", "2 0.5 0.5",
                                        "property uchar red\nproperty uchar flags\n", "200 1 ",
                                        "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
                                        "element camera 0\nproperty float view_px\n",
                                        "0 1\n"));
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_EQ(model.parts[0].mesh.facets.size(), 1U);
    EXPECT_EQ(model.warnings, (std::vector<std::string>{"<memory>: vertex property normals_list is not drawn",
                                                        "<memory>: face properties red, flags are not drawn",
                                                        "<memory>: element edge is not drawn"}));
}

TEST(PlyUnread, AFileOfOnlyWhatRasterDrawsHasNoWarning) {
    EXPECT_EQ(parsed(triangle("property float nx\nproperty float ny\nproperty float nz\nproperty float u\n"
                              "property float v\n",
                              "0 0 1 0.5 0.5", "", ""))
                  .warnings,
              std::vector<std::string>{});
}

// A face's texture coordinates send the file to assimp's reader, which draws them: the vertex
// property neither reader draws is still named once, and what assimp draws is not named.
TEST(PlyUnread, AFileForAssimpsReaderNamesWhatIsNotDrawnOnce) {
    const test_support::ScratchDir dir;
    const std::filesystem::path file = dir / "cloud.ply";
    test_support::write_text(
        file, triangle("property float quality\n", "0.5", "property list uchar float texcoord\n", "6 0 0 1 0 0 1 "));
    const Model model = raster::read_ply(file);
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_FALSE(model.parts[0].mesh.uvs.empty());  // assimp's reader read it
    const std::string name = file.string();
    EXPECT_EQ(model.warnings, std::vector<std::string>{name + ": vertex property quality is not drawn"});
    // read_model reads it here, falls back to a child for assimp, and still names it once.
    const Model routed = raster::read_model(file);
    EXPECT_FALSE(routed.parts.at(0).mesh.uvs.empty());
    EXPECT_EQ(routed.warnings, model.warnings);
}
