// Files that lie, end early or hold what is not a point: raster's own STL reader refuses each in
// one line naming the file and the line or byte, and allocates nothing on a claim alone
// (doc/conventions.md#stl-reader).
#include <raster/io/model.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/stl_file.hpp>

#include "support/scratch.hpp"
#include "support/stl_files.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using raster::Model;
using test_support::ScratchDir;
using test_support::StlFacet;

namespace {

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

std::string error_of(const std::string& text) {
    try {
        static_cast<void>(raster::parse_stl(bytes_of(text)));
    } catch (const std::runtime_error& problem) {
        return problem.what();
    }
    return "";
}

const StlFacet kTriangle{{0, 0, 1}, {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}};

}  // namespace

TEST(HostileStls, ABinaryCountThatLiesIsRefusedNamingWhatItWouldNeed) {
    EXPECT_EQ(error_of(test_support::stl_binary({kTriangle, kTriangle}, "", 3)),
              "<memory>: not an STL model: not 'solid' text, and as a binary STL its triangle count, 3, needs 234 "
              "bytes, and it has 184");
    EXPECT_EQ(error_of("abc"), "<memory>: not an STL model: not 'solid' text, and too short for a binary STL's "
                               "84-byte header");
}

TEST(HostileStls, ABillionTrianglesClaimedBySmallFileAreRefusedBeforeAnyIsAllocated) {
    // Were the claim believed, its arrays would take tens of GiB; the test would fail for memory.
    EXPECT_EQ(error_of(test_support::stl_binary({kTriangle}, "", 1000000000)),
              "<memory>: not an STL model: not 'solid' text, and as a binary STL its triangle count, 1000000000, "
              "needs 50000000084 bytes, and it has 134");
    EXPECT_EQ(error_of(test_support::stl_binary({kTriangle}, "solid by a CAD program", 1000000000)),
              "<memory>: a binary STL whose count lies (as a binary STL its triangle count, 1000000000, needs "
              "50000000084 bytes, and it has 134)");
}

TEST(HostileStls, ABinaryHeaderThatSaysSolidIsReadAsBinaryByItsSize) {
    const Model model = raster::parse_stl(bytes_of(test_support::stl_binary({kTriangle}, "solid exported")));
    EXPECT_EQ(raster::triangle_count(model), 1U);
    const ScratchDir dir;
    test_support::write_text(dir / "solid.stl", test_support::stl_binary({kTriangle}, "solid exported"));
    EXPECT_EQ(raster::triangle_count(raster::read_model(dir / "solid.stl")), 1U);
}

TEST(HostileStls, ABinaryCutMidRecordIsRefusedAsACountThatLies) {
    std::string cut = test_support::stl_binary({kTriangle, kTriangle});
    cut.resize(cut.size() - 20);
    EXPECT_EQ(error_of(cut), "<memory>: not an STL model: not 'solid' text, and as a binary STL its triangle count, "
                             "2, needs 184 bytes, and it has 164");
}

TEST(HostileStls, AnAsciiCutMidFacetOrMidNumberIsRefusedNamingItsLine) {
    const std::string text = test_support::stl_ascii({kTriangle, kTriangle});
    const std::size_t second_vertex = text.rfind("vertex 1");
    EXPECT_EQ(error_of(text.substr(0, second_vertex)), "<memory>:12: the file ends inside facet 2, before 'vertex'");
    EXPECT_EQ(error_of(text.substr(0, second_vertex + 9)),
              "<memory>:12: the file ends inside facet 2, before its numbers");
    EXPECT_EQ(error_of("solid a\nfacet normal 0 0 1\nouter loop\nvertex 1 2 3e"),
              "<memory>:4: '3e' inside facet 1 is not a number");
    EXPECT_EQ(error_of("solid a\nfacet normal 0 0 1\nouter loop\nvertex 1,5 2 3\n"),
              "<memory>:4: '1,5' inside facet 1 is not a number");
    EXPECT_EQ(error_of("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\n"),
              "<memory>:7: 'endloop' expected inside facet 1, not 'endfacet'");
    EXPECT_EQ(error_of("solid a\nfacets\n"), "<memory>:2: 'facet' or 'endsolid' expected, not 'facets'");
}

TEST(HostileStls, NanAndInfiniteCornersAreRefusedNamingTheTriangleAndNormalsAreMade) {
    for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        StlFacet broken = kTriangle;
        broken.corners[1][2] = bad;
        EXPECT_EQ(error_of(test_support::stl_binary({kTriangle, broken})),
                  "<memory>: triangle 2 of 2 has a corner that is not a finite point (byte 134)");
        StlFacet unlit = kTriangle;
        unlit.normal[0] = bad;
        const Model model = raster::parse_stl(bytes_of(test_support::stl_binary({unlit})));
        EXPECT_EQ(model.parts.at(0).mesh.normals.at(0), model.parts[0].mesh.facets.at(0).normal);
    }
    EXPECT_EQ(error_of("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\nvertex 0 1 0\n"
                       "endloop\nendfacet\nendsolid\n"),
              "<memory>:8: facet 1 has a corner that is not a finite point");
    EXPECT_EQ(error_of("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1e39 0\nvertex 0 1 0\n"
                       "endloop\nendfacet\nendsolid\n"),
              "<memory>:8: facet 1 has a corner that is not a finite point");
    // Below float's range is zero, not an error.
    EXPECT_EQ(error_of("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1e-60\nvertex 1 0 0\nvertex 0 1 0\n"
                       "endloop\nendfacet\nendsolid\n"),
              "");
}

TEST(HostileStls, AnEmptySolidOrAZeroCountHasNothingToDraw) {
    EXPECT_EQ(error_of("solid empty\nendsolid empty\n"),
              "<memory>: nothing to draw: no faces, points or lines (its solids hold no facets)");
    EXPECT_EQ(error_of(test_support::stl_binary({})),
              "<memory>: nothing to draw: no faces, points or lines (its triangle count is 0)");
    StlFacet flat = kTriangle;
    flat.corners[2] = flat.corners[1];
    EXPECT_EQ(error_of(test_support::stl_binary({flat})),
              "<memory>: nothing to draw: no faces, points or lines (every triangle has no area)");
}

TEST(HostileStls, BinaryDataInsideAnAsciiSolidIsRefusedNamingItsLine) {
    EXPECT_EQ(
        error_of("solid a\nfacet normal 0 0 1\nouter" + std::string(600, ' ') + "\nloop\n" + std::string(1, '\0')),
        "<memory>:5: binary data, not ASCII STL text");
}

TEST(HostileStls, RecordsAndLinesAcrossBlockEdgesReadWhole) {
    // Over 4 MiB each, so that both span more than one of the reader's blocks.
    const std::vector<StlFacet> sphere = test_support::stl_wavy_sphere(300);
    const std::string binary = test_support::stl_binary(sphere), ascii = test_support::stl_ascii(sphere);
    ASSERT_GT(binary.size(), std::size_t{4} << 20);
    const Model a = raster::parse_stl(bytes_of(binary)), b = raster::parse_stl(bytes_of(ascii));
    EXPECT_EQ(raster::triangle_count(a), raster::triangle_count(b));
    EXPECT_EQ(raster::triangle_count(a), raster::triangle_count(raster::parse_scene_file(bytes_of(binary), "stl")));
    EXPECT_EQ(a.parts.at(0).mesh.positions, b.parts.at(0).mesh.positions);  // shortest decimals read back exactly
    EXPECT_EQ(error_of("solid a\n" + std::string((std::size_t{4} << 20) + 10, 'x')),
              "<memory>:2: a line longer than 4 MiB");
}

TEST(HostileStls, AnAsciiFileWithoutEndsolidIsDrawnWithAWarning) {
    const std::string text = test_support::stl_ascii({kTriangle});
    const Model model = raster::parse_stl(bytes_of(text.substr(0, text.find("endsolid"))));
    ASSERT_EQ(model.warnings.size(), 1U);
    EXPECT_EQ(model.warnings[0], "<memory>: the file ends without 'endsolid'; drawing the facets it holds");
}
