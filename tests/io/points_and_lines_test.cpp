// Points and lines read from OBJ, PLY and glTF into Mesh::points and Mesh::segments, with their
// colours and normals, alone or beside faces (doc/conventions.md#points-and-lines).
#include <raster/image/colour.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/obj_file.hpp>

#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using raster::Model;
using test_support::ScratchDir;

namespace {

const std::filesystem::path kTestModels = "/usr/share/assimp/models";

std::string error_of(const std::string& obj) {
    try {
        (void)raster::parse_obj(obj, "");
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

std::string refusal(const std::filesystem::path& path) {
    try {
        (void)raster::read_model(path);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

// A binary little-endian PLY of points with x y z, nx ny nz and red green blue bytes.
std::string ply_cloud(const std::vector<std::array<float, 6>>& points, const std::vector<std::array<int, 3>>& rgb) {
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(points.size()) +
        "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float "
        "ny\nproperty float nz\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
        char bytes[24];
        std::memcpy(bytes, points[i].data(), sizeof bytes);
        ply.append(bytes, sizeof bytes);
        for (const int c : rgb[i]) ply.push_back(static_cast<char>(c));
    }
    return ply;
}

}  // namespace

TEST(PointsAndLines, ObjPointsAndPolylinesBecomePointsAndSegments) {
    const Model model = raster::parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 1\n"
                                          "p 1 2\np 3\nl 1 2 3 4\nl 1/1 3/2\n",
                                          "");
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    EXPECT_TRUE(mesh.facets.empty());
    ASSERT_EQ(mesh.points.size(), 3U);
    ASSERT_EQ(mesh.segments.size(), 4U);  // three from the polyline of four, one from the pair
    EXPECT_EQ(mesh.positions[mesh.points[2]], glm::vec3(1, 1, 0));
    EXPECT_EQ(mesh.positions[mesh.segments[0][0]], glm::vec3(0, 0, 0));
    EXPECT_EQ(mesh.positions[mesh.segments[2][1]], glm::vec3(0, 1, 0));
    EXPECT_EQ(mesh.positions[mesh.segments[3][1]], glm::vec3(1, 1, 0));
    EXPECT_EQ(mesh.normals[mesh.points[0]], glm::vec3(0.0F));  // no normal: drawn in its colour
    EXPECT_EQ(raster::point_count(model), 3U);
    EXPECT_EQ(raster::segment_count(model), 4U);
}

TEST(PointsAndLines, PointsAndLinesBesideFacesShareTheModelAndItsBounds) {
    const Model model = raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 0 0 -7\nvn 0 0 1\n"
                                          "f 1 2 3\np 4//1\nl 1 5\n",
                                          "");
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_EQ(raster::triangle_count(model), 1U);
    ASSERT_EQ(raster::point_count(model), 1U);
    EXPECT_EQ(raster::segment_count(model), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    EXPECT_EQ(mesh.normals[mesh.points[0]], glm::vec3(0, 0, -1));  // mirrored into raster's world as faces are
    const raster::Bounds bounds = raster::bounds_of(model);
    EXPECT_EQ(bounds.high.x, 5.0);
    EXPECT_EQ(bounds.high.z, 7.0);
}

TEST(PointsAndLines, OutOfRangeIndicesInPointsAndLinesAreOneLineErrorsNamingTheLine) {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(error_of(triangle + "p 9\n"), "<memory>:4: point names vertex 9, but 3 are defined before it");
    EXPECT_EQ(error_of(triangle + "l 1 2 -5\n"), "<memory>:4: line names vertex -5, but 3 are defined before it");
    EXPECT_EQ(error_of(triangle + "l 1/4 2/1\n"),
              "<memory>:4: line names texture coordinate 4, but 0 are defined before it");
    EXPECT_EQ(error_of(triangle + "p 0\n"), "<memory>:4: vertex index 0: OBJ counts from 1");
    EXPECT_EQ(error_of(triangle + "l 1 /2\n"), "<memory>:4: vertex '/2' is not of the form v, v/vt, v/vt/vn or v//vn");
}

TEST(PointsAndLines, NonFinitePointCoordinatesAreRefusedInObjAndSkippedWithAWarningInPly) {
    EXPECT_EQ(error_of("v 0 0 0\nv nan 0 0\np 1 2\n"),
              "<memory>:3: the point uses vertex 2, but line 2 gives it 'nan', which is not a finite number");
    const ScratchDir dir;
    const float inf = INFINITY;
    test_support::write_text(dir / "holes.ply",
                             ply_cloud({{0, 0, 0, 0, 0, 1}, {inf, 0, 0, 0, 0, 1}, {1, 1, 1, 0, 0, 1}},
                                       {{{255, 0, 0}}, {{0, 255, 0}}, {{0, 0, 255}}}));
    const Model model = raster::read_model(dir / "holes.ply");
    EXPECT_EQ(raster::point_count(model), 2U);
    ASSERT_EQ(model.warnings.size(), 1U);
    EXPECT_EQ(model.warnings[0],
              (dir / "holes.ply").string() + ": skipped 1 points or line ends that are not finite points");
}

TEST(PointsAndLines, AnObjOfVerticesAloneIsAPointCloudWithTheNormalsInTheirOrder) {
    const Model model = raster::parse_obj("vn 0 0 1\nv 0 0 0\nvn 1 0 0\nv 1 0 0\n", "");
    ASSERT_EQ(raster::point_count(model), 2U);
    const raster::Mesh& mesh = model.parts.at(0).mesh;
    EXPECT_EQ(mesh.normals[mesh.points[0]], glm::vec3(0, 0, -1));
    EXPECT_EQ(mesh.normals[mesh.points[1]], glm::vec3(1, 0, 0));
    EXPECT_EQ(raster::point_count(raster::parse_obj("vn 0 0 1\nv 0 0 0\nv 1 0 0\n", "")), 2U);  // no pairs: unlit
}

TEST(PointsAndLines, AModelWithNothingDrawableSaysSo) {
    EXPECT_EQ(error_of("# nothing\n"), "<memory>: nothing to draw: no faces, points or lines");
    EXPECT_EQ(error_of("v 0 0 0\nf 1\n"), "<memory>: nothing to draw: no faces, points or lines");
    EXPECT_EQ(error_of("v 0 0 0\nl 1\n"), "<memory>: nothing to draw: no faces, points or lines");
    const ScratchDir dir;
    test_support::write_text(dir / "none.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty "
                                               "float y\nproperty float z\nend_header\n");
    EXPECT_EQ(
        refusal(dir / "none.ply"),
        (dir / "none.ply").string() + ": nothing to draw: no faces, points or lines (its header declares no vertices)");
    const Model warned = raster::parse_obj("v 0 0 0\nl 1\np 1\n", "");
    EXPECT_EQ(warned.warnings,
              std::vector<std::string>{"<memory>:2: a line (l) of fewer than 2 vertices draws nothing; skipped"});
}

TEST(PointsAndLines, APlyPointCloudKeepsItsSrgbColoursAndNormals) {
    const ScratchDir dir;
    test_support::write_text(dir / "cloud.ply",
                             ply_cloud({{0, 0, 0, 0, 0, 1}, {1, 2, 3, 1, 0, 0}}, {{{255, 0, 0}}, {{0, 128, 255}}}));
    const Model model = raster::read_model(dir / "cloud.ply");
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    ASSERT_EQ(mesh.points.size(), 2U);
    EXPECT_TRUE(mesh.facets.empty());
    EXPECT_EQ(mesh.positions[mesh.points[1]], glm::vec3(1, 2, -3));
    EXPECT_EQ(mesh.normals[mesh.points[0]], glm::vec3(0, 0, -1));
    ASSERT_EQ(mesh.colours.size(), mesh.positions.size());
    EXPECT_EQ(mesh.colours[mesh.points[0]], (raster::LinearRgb{1, 0, 0}));
    EXPECT_NEAR(mesh.colours[mesh.points[1]].g, 0.2158605F, 1e-5F);  // the sRGB byte 128 in linear light
}

// Every byte a colour channel can hold comes out as the sRGB formula gives it for that byte read
// as byte / 255, whether looked up or worked out.
TEST(PointsAndLines, EveryPlyColourByteIsTheSrgbFormulasValue) {
    const ScratchDir dir;
    std::vector<std::array<float, 6>> points;
    std::vector<std::array<int, 3>> rgb;
    for (int b = 0; b < 256; ++b) {
        points.push_back({static_cast<float>(b), 0, 0, 0, 0, 0});
        rgb.push_back({b, 255 - b, b});
    }
    test_support::write_text(dir / "bytes.ply", ply_cloud(points, rgb));
    const Model model = raster::read_model(dir / "bytes.ply");
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    ASSERT_EQ(mesh.points.size(), 256U);
    ASSERT_EQ(mesh.colours.size(), mesh.positions.size());
    const auto formula = [](int b) {
        return static_cast<float>(raster::linear_from_srgb_channel(static_cast<float>(b) / 255.0F));
    };
    for (std::size_t k = 0; k < 256; ++k) {
        const std::uint32_t i = mesh.points[k];
        const int b = static_cast<int>(mesh.positions[i].x);
        EXPECT_EQ(mesh.colours[i].r, formula(b)) << "byte " << b;
        EXPECT_EQ(mesh.colours[i].g, formula(255 - b)) << "byte " << 255 - b;
    }
}

TEST(PointsAndLines, AssimpsPointAndLineModelsRead) {
    if (!std::filesystem::exists(kTestModels / "OBJ/testpoints.obj")) GTEST_SKIP() << "assimp-testmodels is missing";
    const Model points = raster::read_model(kTestModels / "OBJ/testpoints.obj");
    EXPECT_EQ(raster::point_count(points), 24U);
    EXPECT_EQ(raster::triangle_count(points), 0U);
    EXPECT_GT(raster::segment_count(raster::read_model(kTestModels / "OBJ/testline.obj")), 0U);
    EXPECT_GT(raster::point_count(raster::read_model(kTestModels / "OBJ/point_cloud.obj")), 0U);
    const Model cloud = raster::read_model(kTestModels / "PLY/points.ply");
    ASSERT_GT(raster::point_count(cloud), 0U);
    ASSERT_EQ(cloud.parts.size(), 1U);
    EXPECT_FALSE(cloud.parts[0].mesh.colours.empty());
    EXPECT_NE(cloud.parts[0].mesh.normals[0], glm::vec3(0.0F));
}

TEST(PointsAndLines, GltfPointsLinesLineLoopsAndLineStripsRead) {
    const std::filesystem::path folder = kTestModels / "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode";
    if (!std::filesystem::exists(folder)) GTEST_SKIP() << "assimp-testmodels is missing";
    EXPECT_EQ(raster::point_count(raster::read_model(folder / "Mesh_PrimitiveMode_00.gltf")), 1024U);
    // LINES of 8 vertices, a LINE_LOOP of 4 (closed) and a LINE_STRIP of 5: four segments each.
    for (const char* name : {"Mesh_PrimitiveMode_01.gltf", "Mesh_PrimitiveMode_02.gltf", "Mesh_PrimitiveMode_03.gltf",
                             "Mesh_PrimitiveMode_09.gltf", "Mesh_PrimitiveMode_10.gltf"}) {
        const Model model = raster::read_model(folder / name);
        EXPECT_EQ(raster::segment_count(model), 4U) << name;
        EXPECT_EQ(raster::triangle_count(model), 0U) << name;
    }
    const Model loop = raster::read_model(folder / "Mesh_PrimitiveMode_02.gltf");
    const raster::Mesh& mesh = loop.parts.at(0).mesh;
    EXPECT_EQ(mesh.positions[mesh.segments[3][1]], mesh.positions[mesh.segments[0][0]]);  // the loop closes
}
