// PLY headers are checked by raster before assimp, which loops forever on one without end_header.
#include <raster/io/model_file.hpp>

#include "io/ply_header.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

std::string problem_of(const std::string& text) {
    const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    return raster::detail::ply_header_problem(bytes);
}

const std::string kHeader =
    "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

}  // namespace

TEST(PlyHeader, AWellFormedHeaderPassesAndStrayLinesAreSkippedAsAssimpSkipsThem) {
    EXPECT_EQ(problem_of(kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "");
    EXPECT_EQ(
        problem_of(
            "ply\r\nformat binary_little_endian 1.0\r\nCreated by Blender3D 247\r\nelement vertex 0\r\nend_header\r\n"),
        "");
}

TEST(PlyHeader, AHeaderWithoutEndHeaderOrWithUnknownTypesIsRefusedWithItsLine) {
    std::string cut = kHeader;
    cut.replace(cut.find("end_header"), 10, "isend_header");
    EXPECT_EQ(problem_of(cut), "the PLY header has no end_header line in its first 64 KiB");
    EXPECT_EQ(
        problem_of("ply\nformat ascii 1.0\nelement vertex 3\nproperty fl$at x\nend_header\n"),
        "the PLY header has a property line that is not 'property TYPE NAME' or 'property list TYPE TYPE NAME' (line 4)");
    EXPECT_EQ(problem_of("ply\nformat ascii 1.0\nelement vertex lots\nend_header\n"),
              "the PLY header has an element line that is not 'element NAME COUNT' (line 3)");
    EXPECT_EQ(
        problem_of("ply\nformat ascii 2.0\nend_header\n"),
        "the PLY header has no 'format ascii|binary_little_endian|binary_big_endian 1.0' line after 'ply' (line 2)");
    EXPECT_EQ(problem_of("ply\nproperty float x\nend_header\n").empty(), false);
    EXPECT_EQ(problem_of("ply?\nformat ascii 1.0\nend_header\n"), "the PLY header does not begin with 'ply' (line 1)");
}

TEST(PlyHeader, TheFileThatHungAssimpIsOneLineThroughTheLoader) {
    std::string hung = kHeader;
    hung.replace(hung.find("end_header"), 10, "isend_header");
    const std::vector<std::uint8_t> bytes(hung.begin(), hung.end());
    try {
        (void)raster::parse_scene_file(bytes, "ply");
        FAIL() << "accepted";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "<memory>: the PLY header has no end_header line in its first 64 KiB");
    }
}
