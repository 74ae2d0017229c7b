// Reading OBJ models: geometry, normals, materials, textures, and every kind of bad input.
#include <raster/model.hpp>
#include <raster/obj_file.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using raster::Model;
using raster::parse_obj;

namespace {

// The message parse_obj throws, or "" when it reads the model.
std::string error_of(const std::string& obj, const std::string& mtl = "") {
    try {
        (void)parse_obj(obj, mtl);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
    for (const std::string& line : lines) {
        if (line.find(text) != std::string::npos) return true;
    }
    return false;
}

}  // namespace

TEST(ObjFile, QuadsAreSplitAndCounterClockwiseFacesTurnTowardTheirViewer) {
    // A square facing +Z in OBJ's right-handed coordinates, counter-clockwise seen from +Z.
    const Model model = parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", "");
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::Mesh& mesh = model.parts[0].mesh;
    ASSERT_EQ(mesh.facets.size(), 2U);
    // Mirrored into raster's left-handed world that viewer stands at -Z: the normals point there.
    for (const raster::Facet& facet : mesh.facets) {
        EXPECT_EQ(facet.normal, glm::vec3(0.0F, 0.0F, -1.0F));
        const glm::vec3 a = mesh.positions[facet.corners[0]], b = mesh.positions[facet.corners[1]], c = mesh.positions[facet.corners[2]];
        EXPECT_EQ(raster::facet_normal(a, b, c), facet.normal);  // clockwise from outside, raster's rule
    }
    EXPECT_EQ(raster::triangle_count(model), 2U);
    EXPECT_EQ(model.parts[0].material.diffuse, raster::default_model_material().diffuse);
}

TEST(ObjFile, MissingNormalsAreSmoothBelowTheCreaseAngleAndCreasedAbove) {
    // Two triangles folded by 20 degrees along the shared edge 1-2.
    const std::string fold = "v 0 0 0\nv 0 1 0\nv 1 0 0\nv -1 0 " + std::to_string(std::tan(0.349066)) + "\nf 1 3 2\nf 1 2 4\n";
    raster::ObjOptions smooth;
    smooth.crease_degrees = 30.0;
    const Model smoothed = parse_obj(fold, "", smooth);
    EXPECT_EQ(smoothed.parts[0].mesh.positions.size(), 4U);  // shared edge, shared normals
    raster::ObjOptions sharp;
    sharp.crease_degrees = 10.0;
    const Model creased = parse_obj(fold, "", sharp);
    EXPECT_EQ(creased.parts[0].mesh.positions.size(), 6U);  // each facet its own corners
    for (std::size_t i = 0; i < creased.parts[0].mesh.positions.size(); ++i) {
        const raster::Mesh& mesh = creased.parts[0].mesh;
        const bool first = mesh.normals[i] == mesh.facets[0].normal, second = mesh.normals[i] == mesh.facets[1].normal;
        EXPECT_TRUE(first || second);
    }
    // Normals in the file win, and are mirrored like the positions.
    const Model given = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0.6 0 0.8\nf 1//1 2//1 3//1\n", "");
    EXPECT_NEAR(given.parts[0].mesh.normals[0].x, 0.6F, 1e-6F);
    EXPECT_NEAR(given.parts[0].mesh.normals[0].z, -0.8F, 1e-6F);
}

TEST(ObjFile, EachMaterialIsAPartWithItsColours) {
    const std::string mtl = "newmtl matte\nKd 0.5 0.25 0.125\n"
                            "newmtl shiny\nKd 1 1 1\nKs 0.5 0.5 0.5\nNs 64\nKe 0.1 0 0\n";
    const std::string obj = "mtllib any.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                            "usemtl matte\nf 1 2 3\nusemtl shiny\nf 2 4 3\n";
    const Model model = parse_obj(obj, mtl);
    ASSERT_EQ(model.parts.size(), 2U);
    EXPECT_EQ(model.parts[0].material_name, "matte");
    EXPECT_EQ(model.parts[0].material.diffuse, (raster::LinearRgb{0.5F, 0.25F, 0.125F}));
    EXPECT_FALSE(model.parts[0].material.shininess.has_value());  // no Ks: no highlight
    EXPECT_EQ(model.parts[1].material.specular, (raster::LinearRgb{0.5F, 0.5F, 0.5F}));
    EXPECT_EQ(model.parts[1].material.shininess, 64.0F);
    EXPECT_EQ(model.parts[1].material.emissive, (raster::LinearRgb{0.1F, 0.0F, 0.0F}));
}

TEST(ObjFile, BadIndicesAndPointsAreOneLineErrors) {
    const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(error_of(triangle + "f 1 2 9\n"), "<memory>:4: face names vertex 9, but 3 are defined before it");
    EXPECT_EQ(error_of(triangle + "f 1 2 3 9\n"), "<memory>:4: face names vertex 9, but 3 are defined before it");  // a quad too
    EXPECT_EQ(error_of(triangle + "f 1 2 -7\n"), "<memory>:4: face names vertex -7, but 3 are defined before it");
    EXPECT_EQ(error_of("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"), "<memory>:2: face names vertex 2, but 1 is defined before it");
    EXPECT_EQ(error_of(triangle + "vt 0 0\nf 1/1 2/5 3/1\n"), "<memory>:5: face names texture coordinate 5, but 1 is defined before it");
    EXPECT_EQ(error_of(triangle + "f 1//1 2//1 3//1\n"), "<memory>:4: face names normal 1, but 0 are defined before it");
    EXPECT_EQ(error_of(triangle + "f 0 1 2\n"), "<memory>:4: vertex index 0: OBJ counts from 1");
    EXPECT_EQ(error_of(triangle + "f 1 x 3\n"), "<memory>:4: 'x' is not a vertex index");
    std::string many = triangle + "f";
    for (std::size_t i = 0; i <= raster::kMaxFaceCorners; ++i) many += " " + std::to_string(i % 3 + 1);
    EXPECT_EQ(error_of(many + "\n"), "<memory>:4: a face of more than 1024 corners");
    EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 -1e39 0\nf 1 2 3\n"), "<memory>: vertex 3 is not a finite point");
    EXPECT_EQ(error_of("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"), "<memory>: vertex 2 is not a finite point");
    EXPECT_EQ(error_of(""), "<memory>: no faces to draw");
    EXPECT_EQ(error_of(triangle), "<memory>: no faces to draw");
    EXPECT_EQ(error_of("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n"), "<memory>: no faces to draw");  // no area
}

TEST(ObjFile, HugeAndTinyModelsKeepTheirFaces) {
    for (const char* scale : {"1e10", "1e-12", "3e37"}) {
        const std::string s(scale);
        const Model model = parse_obj("v 0 0 0\nv " + s + " 0 0\nv 0 " + s + " 0\nf 1 2 3\n", "");
        ASSERT_EQ(raster::triangle_count(model), 1U) << scale;
        EXPECT_EQ(model.parts[0].mesh.facets[0].normal, glm::vec3(0, 0, -1)) << scale;
    }
}

TEST(ObjFile, AMissingKdIsTinyobjloadersGreyAndEachMapFileIsReadOnce) {
    const test_support::ScratchDir dir;
    test_support::write_png(dir / "big.png", test_support::checkerboard(2, 2, {10, 20, 30}, {40, 50, 60}));
    test_support::write_text(dir / "two.mtl", "newmtl a\nmap_Kd big.png\nnewmtl b\nKd 1 1 1\nmap_Kd ./big.png\n");
    std::string obj = test_support::textured_cube_obj("two.mtl", "a");
    obj += "usemtl b\nf 1/1 2/2 3/3\n";
    test_support::write_text(dir / "two.obj", obj);
    const Model model = raster::read_obj(dir / "two.obj");
    ASSERT_EQ(model.parts.size(), 2U);
    EXPECT_EQ(model.parts[0].material.diffuse, (raster::LinearRgb{0.6F, 0.6F, 0.6F}));  // tinyobjloader's default Kd
    ASSERT_NE(model.parts[0].texture, nullptr);
    EXPECT_EQ(model.parts[0].texture, model.parts[1].texture);  // big.png and ./big.png: one file, read once
}

TEST(ObjFile, FacesWithFewerThanThreeCornersAreSkippedWithAWarning) {
    const Model model = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\nf 1 2 3\n", "");
    EXPECT_EQ(raster::triangle_count(model), 1U);
    EXPECT_FALSE(model.warnings.empty());
}

TEST(ObjFile, MalformedTextNeverCrashes) {
    for (const char* text : {"v 1 abc 3\nf 1 1 1\n", "f\n", "f / / /\n", "v\nv\nv\nf 1 2 3\n", "vt 1e999 -1e999\n", "usemtl\nmtllib\n",
                             "f 0 0 0\n", "v 1 2 3\nf -1 -1 -1\n", "f 2147483647 -2147483648 1\n", "\x00\xff\xfe garbage\n"}) {
        (void)error_of(text, "newmtl\nKd x y z\nNs nan\nmap_Kd\n");
    }
}

TEST(ObjFile, TexturesResolveBesideTheMtlEvenWithSpacesAndNonAsciiNames) {
    const test_support::ScratchDir dir;
    const std::filesystem::path folder = dir / "mödel dir";
    std::filesystem::create_directories(folder / "maps");
    test_support::write_png(folder / "maps" / "wood grain é.png", test_support::checkerboard(2, 4, {200, 100, 50}, {20, 10, 5}));
    test_support::write_text(folder / "box.mtl", "newmtl wood\nKd 1 1 1\nmap_Kd maps/wood grain é.png\n");
    test_support::write_text(folder / "bóx.obj", test_support::textured_cube_obj("box.mtl", "wood"));
    const Model model = raster::read_obj(folder / "bóx.obj");
    ASSERT_EQ(model.parts.size(), 1U);
    ASSERT_NE(model.parts[0].texture, nullptr);
    EXPECT_EQ(model.parts[0].texture->width(), 8);
    EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
}

TEST(ObjFile, AMissingTextureOrMaterialFileWarnsAndDrawsTheColour) {
    const test_support::ScratchDir dir;
    test_support::write_text(dir / "box.mtl", "newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd nowhere.png\n");
    test_support::write_text(dir / "box.obj", test_support::textured_cube_obj("box.mtl", "wood"));
    const Model model = raster::read_obj(dir / "box.obj");
    EXPECT_EQ(model.parts.at(0).texture, nullptr);
    EXPECT_TRUE(mentions(model.warnings, "nowhere.png")) << ::testing::PrintToString(model.warnings);
    test_support::write_text(dir / "lost.obj", test_support::textured_cube_obj("lost.mtl", "wood"));
    const Model lost = raster::read_obj(dir / "lost.obj");
    EXPECT_EQ(lost.parts.at(0).material.diffuse, raster::default_model_material().diffuse);
    EXPECT_TRUE(mentions(lost.warnings, "lost.mtl")) << ::testing::PrintToString(lost.warnings);
}

TEST(ObjFile, DirectoriesAndMissingFilesAreOneLineErrorsNamingThem) {
    const test_support::ScratchDir dir;
    for (const std::filesystem::path& path : {dir.path(), dir / "missing.obj"}) {
        try {
            (void)raster::read_obj(path);
            ADD_FAILURE() << path << " was read";
        } catch (const std::runtime_error& error) {
            EXPECT_EQ(std::string(error.what()).rfind(path.string() + ": ", 0), 0U) << error.what();
        }
    }
}
