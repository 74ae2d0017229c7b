// OBJ's vertex colours, `v x y z r g b`, read as sRGB into Mesh::colours
// (doc/conventions.md#vertex-colours).
#include <raster/io/model_file.hpp>
#include <raster/io/obj_file.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using raster::Model;

TEST(ObjVertexColours, RgbAfterAVertexIsAnSrgbColourInLinearLight) {
    const Model model = raster::parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 1\nf 1 2 3\np 2\n", "");
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    ASSERT_EQ(mesh.colours.size(), mesh.positions.size());
    EXPECT_EQ(mesh.colours[mesh.facets[0].corners[0]], (raster::LinearRgb{1, 0, 0}));
    EXPECT_NEAR(mesh.colours[mesh.points[0]].g, 0.2140411F, 1e-5F);  // sRGB 0.5
    EXPECT_TRUE(model.warnings.empty());
}

TEST(ObjVertexColours, ColoursOutOfRangeAreClamped) {
    const Model model = raster::parse_obj("v 0 0 0 2 -1 1\nv 1 0 0 0 0 0\nv 0 1 0 0 0 0\nf 1 2 3\n", "");
    const raster::Mesh& mesh = model.parts.at(0).mesh;
    ASSERT_FALSE(mesh.colours.empty());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (mesh.positions[i] == glm::vec3(0.0F)) {
            EXPECT_EQ(mesh.colours[i], (raster::LinearRgb{1, 0, 1}));
        }
    }
}

TEST(ObjVertexColours, ColoursOnSomeVerticesOnlyAreDroppedWithOneWarning) {
    const Model model = raster::parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "");
    EXPECT_TRUE(model.parts.at(0).mesh.colours.empty());
    EXPECT_EQ(model.warnings, std::vector<std::string>{"<memory>: 1 of 3 vertices give a colour, and OBJ's colours are "
                                                       "all or none; drawing none"});
}

TEST(ObjVertexColours, AssimpsCubeWithVertexColoursComesOutColoured) {
    const std::filesystem::path cube = "/usr/share/assimp/models/OBJ/cube_with_vertexcolors.obj";
    if (!std::filesystem::exists(cube)) GTEST_SKIP() << "assimp-testmodels is missing";
    const Model model = raster::read_model(cube);
    ASSERT_FALSE(model.parts.empty());
    const raster::Mesh& mesh = model.parts[0].mesh;
    ASSERT_EQ(mesh.colours.size(), mesh.positions.size());
    bool any_not_grey = false;
    for (const raster::LinearRgb& c : mesh.colours) any_not_grey = any_not_grey || c.r != c.g || c.g != c.b;
    EXPECT_TRUE(any_not_grey);
}
