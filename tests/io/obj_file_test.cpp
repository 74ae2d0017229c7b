// Reading OBJ models: geometry, normals, materials, textures, bad input; stays whole as the OBJ suite.
#include <raster/io/input_file.hpp>
#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

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
        const glm::vec3 a = mesh.positions[facet.corners[0]], b = mesh.positions[facet.corners[1]],
                        c = mesh.positions[facet.corners[2]];
        EXPECT_EQ(raster::facet_normal(a, b, c), facet.normal);  // clockwise from outside, raster's rule
    }
    EXPECT_EQ(raster::triangle_count(model), 2U);
    EXPECT_EQ(model.parts[0].material.diffuse, raster::default_model_material().diffuse);
}

TEST(ObjFile, MissingNormalsAreSmoothBelowTheCreaseAngleAndCreasedAbove) {
    // Two triangles folded by 20 degrees along the shared edge 1-2.
    const std::string fold =
        "v 0 0 0\nv 0 1 0\nv 1 0 0\nv -1 0 " + std::to_string(std::tan(0.349066)) + "\nf 1 3 2\nf 1 2 4\n";
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
    EXPECT_EQ(error_of(triangle + "f 1 2 3 9\n"),
              "<memory>:4: face names vertex 9, but 3 are defined before it");  // a quad too
    EXPECT_EQ(error_of(triangle + "f 1 2 -7\n"), "<memory>:4: face names vertex -7, but 3 are defined before it");
    EXPECT_EQ(error_of("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"),
              "<memory>:2: face names vertex 2, but 1 is defined before it");
    EXPECT_EQ(error_of(triangle + "vt 0 0\nf 1/1 2/5 3/1\n"),
              "<memory>:5: face names texture coordinate 5, but 1 is defined before it");
    EXPECT_EQ(error_of(triangle + "f 1//1 2//1 3//1\n"),
              "<memory>:4: face names normal 1, but 0 are defined before it");
    EXPECT_EQ(error_of(triangle + "f 0 1 2\n"), "<memory>:4: vertex index 0: OBJ counts from 1");
    EXPECT_EQ(error_of(triangle + "f 1 x 3\n"), "<memory>:4: 'x' is not a vertex index");
    std::string many = triangle + "f";
    for (std::size_t i = 0; i <= raster::kMaxFaceCorners; ++i) many += " " + std::to_string(i % 3 + 1);
    EXPECT_EQ(error_of(many + "\n"), "<memory>:4: a face of more than 1024 corners");
    EXPECT_EQ(
        error_of("v 0 0 0\nv 1 0 0\nv 0 -1e39 0\nf 1 2 3\n"),
        "<memory>:4: the face uses vertex 3, but line 3 gives it '-1e39', which is beyond the largest coordinate raster stores");
    EXPECT_EQ(error_of(""), "<memory>: nothing to draw: no faces, points or lines");
    EXPECT_EQ(error_of(triangle), "");  // vertices alone are a point cloud
    EXPECT_EQ(error_of("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n"), "<memory>: every face has no area");
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

TEST(ObjFile, MalformedTextIsRefusedInOneLineSayingWhere) {
    const std::pair<std::string, std::string> cases[] = {
        {"v 1 abc 3\nf 1 1 1\n",
         "<memory>:2: the face uses vertex 1, but line 1 gives it 'abc', which is not a number"},
        {"f\n", "<memory>: nothing to draw: no faces, points or lines"},
        {"f / / /\n", "<memory>:1: corner '/' is not of the form v, v/vt, v/vt/vn or v//vn"},
        {"v\nv\nv\nf 1 2 3\n", "<memory>:4: face names vertex 1, but 0 are defined before it"},
        {"vt 1e999 -1e999\n", "<memory>: nothing to draw: no faces, points or lines"},
        {"usemtl\nmtllib\n", "<memory>: nothing to draw: no faces, points or lines"},
        {"f 0 0 0\n", "<memory>:1: vertex index 0: OBJ counts from 1"},
        {"v 1 2 3\nf -1 -1 -1\n", "<memory>: every face has no area"},
        {"f 2147483647 -2147483648 1\n", "<memory>:1: face names vertex 2147483647, but 0 are defined before it"},
        {std::string("\x00\xff\xfe garbage\n", 12), "<memory>: nothing to draw: no faces, points or lines"},
    };
    for (const auto& [text, message] : cases)
        EXPECT_EQ(error_of(text, "newmtl\nKd x y z\nNs nan\nmap_Kd\n"), message) << raster::printable(text);
}

TEST(ObjFile, AMalformedMaterialLibraryLeavesFiniteColoursNoShininessAndNoMap) {
    const Model model =
        parse_obj("mtllib m.mtl\nusemtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "newmtl\nKd x y z\nNs nan\nmap_Kd\n");
    ASSERT_EQ(raster::triangle_count(model), 1U);
    const auto& material = model.parts[0].material;
    for (const auto& colour : {material.emissive, material.diffuse, material.specular}) {
        EXPECT_TRUE(std::isfinite(colour.r) && std::isfinite(colour.g) && std::isfinite(colour.b));
    }
    EXPECT_FALSE(material.shininess.has_value()) << "Ns nan is no exponent";
    EXPECT_EQ(model.parts[0].texture, nullptr);
    EXPECT_NE(material.diffuse.r, raster::default_model_material().diffuse.r) << "a bare usemtl picks the bare newmtl";
}

TEST(ObjFile, AUsemtlWithoutANameIsTheDefaultMaterialWhereNoLibraryHasANamelessOne) {
    const Model model = parse_obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\nusemtl\nf 1 3 2\n",
                                  "newmtl red\nKd 1 0 0\n");
    ASSERT_EQ(model.parts.size(), 2U);
    EXPECT_EQ(model.parts[0].material.diffuse.g, raster::default_model_material().diffuse.g);
    EXPECT_EQ(model.parts[1].material.diffuse.r, 1.0F);
    EXPECT_EQ(model.parts[1].material.diffuse.g, 0.0F);
}

TEST(ObjFile, TexturesResolveBesideTheMtlEvenWithSpacesAndNonAsciiNames) {
    const test_support::ScratchDir dir;
    const std::filesystem::path folder = dir / "mödel dir";
    std::filesystem::create_directories(folder / "maps");
    test_support::write_png(folder / "maps" / "wood grain é.png",
                            test_support::checkerboard(2, 4, {200, 100, 50}, {20, 10, 5}));
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

TEST(ObjFile, NonFiniteCoordinatesAFaceUsesAreRefusedWithTheirLine) {
    const std::string face = "f 1 2 3\n";
    EXPECT_EQ(error_of("v 0 0 nan\nv 1 0 0\nv 0 1 0\n" + face),
              "<memory>:4: the face uses vertex 1, but line 1 gives it 'nan', which is not a finite number");
    EXPECT_EQ(error_of("v 0 0 0\nv inf 0 0\nv 0 1 0\n" + face),
              "<memory>:4: the face uses vertex 2, but line 2 gives it 'inf', which is not a finite number");
    EXPECT_EQ(
        error_of("v 0 0 0\nv 1 0 0\nv 0 1e39 0\n" + face),
        "<memory>:4: the face uses vertex 3, but line 3 gives it '1e39', which is beyond the largest coordinate raster stores");
    EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 zero\n" + face),
              "<memory>:4: the face uses vertex 3, but line 3 gives it 'zero', which is not a number");
    EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -nan\nf 1//1 2//1 3//1\n"),
              "<memory>:5: the face uses normal 1, but line 4 gives it '-nan', which is not a finite number");
    EXPECT_EQ(
        error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 -infinity\nf 1/1 2/1 3/-1\n"),
        "<memory>:5: the face uses texture coordinate 1, but line 4 gives it '-infinity', which is not a finite number");
    // +1 and exponents are numbers as written.
    EXPECT_EQ(error_of("v +1 0 0\nv 1e0 1 0\nv 0 1 0.5E-1\n" + face), "");
}

TEST(ObjFile, NonFiniteCoordinatesNoFaceUsesAreAWarning) {
    const Model model = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nf 1 2 3\n", "");
    EXPECT_EQ(
        model.warnings,
        (std::vector<std::string>{"<memory>:4: vertex 4 has 'nan', which is not a finite number; no face uses it"}));
}

TEST(ObjFile, FaceCornersOfNoOBJFormAreRefusedInOurWordsWithControlBytesShown) {
    const std::string points = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(error_of(points + "f 1/ 2/ 3/\n"),
              "<memory>:4: corner '1/' is not of the form v, v/vt, v/vt/vn or v//vn");
    EXPECT_EQ(error_of(points + "f 1/1/1/1 2 3\n"),
              "<memory>:4: corner '1/1/1/1' is not of the form v, v/vt, v/vt/vn or v//vn");
    EXPECT_EQ(error_of(points + std::string("f 1 2\0 3\n", 9)), "<memory>:4: '2\\x00' is not a vertex index");
    EXPECT_EQ(error_of(points + "f 1 2 \x1b[2J\n"), "<memory>:4: '\\x1b[2J' is not a vertex index");
}

TEST(ObjFile, AMissingMaterialLibraryIsOneWarning) {
    const test_support::ScratchDir dir;
    test_support::write_text(dir / "m.obj", test_support::textured_cube_obj("missing.mtl", "skin"));
    const Model model = raster::read_obj(dir / "m.obj");
    ASSERT_EQ(model.warnings.size(), 1U) << ::testing::PrintToString(model.warnings);
    EXPECT_EQ(model.warnings[0], (dir / "m.obj").string() + ":1: material library '" + (dir / "missing.mtl").string() +
                                     "' does not exist; drawing the default material");
    const Model unknown = parse_obj(test_support::textured_cube_obj("lib.mtl", "absent"), "newmtl other\nKd 1 0 0\n");
    EXPECT_EQ(
        unknown.warnings,
        (std::vector<std::string>{
            "<memory>:14: material 'absent' is in none of the file's material libraries; drawing the default material"}));
}

TEST(ObjFile, ALineLongerThanTheCapIsRefusedWithItsNumberBeforeItIsHeld) {
    const test_support::ScratchDir dir;
    test_support::write_text(dir / "long.obj",
                             "v 0 0 0\n#" + std::string(raster::kMaxObjLineBytes, 'x') + "\nv 1 0 0\n");
    try {
        (void)raster::read_obj(dir / "long.obj");
        ADD_FAILURE() << "a line over the cap was read";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()),
                  (dir / "long.obj").string() + ":2: a line longer than 4 MiB, the most raster reads in one line");
    }
}

TEST(ObjFile, LineEndsByteOrderMarksAndBareKeywordsAreReadAsTinyobjloaderReadsThem) {
    const test_support::ScratchDir dir;
    // Old Mac line ends: a lone "\r" ends each line, so the nan is seen and refused.
    test_support::write_text(dir / "mac.obj", "v 0 0 nan\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
    EXPECT_THROW((void)raster::read_obj(dir / "mac.obj"), std::runtime_error);
    // A byte order mark before the first vertex: it is still the first vertex.
    test_support::write_text(dir / "bom.obj", "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(raster::triangle_count(raster::read_obj(dir / "bom.obj")), 1U);
    EXPECT_EQ(raster::triangle_count(parse_obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "")), 1U);
    // "v" alone is no vertex, so the nan is vertex 2, and the face uses it.
    EXPECT_EQ(error_of("v 1 0 0\nv\nv 0 0 nan\nv 0 1 0\nv 0 0 1\nf 1 2 4\n"),
              "<memory>:6: the face uses vertex 2, but line 3 gives it 'nan', which is not a finite number");
    EXPECT_EQ(error_of("v 1 0 0\nv 0 0\nv 0 1 0\nf 1 2 3\n"),
              "<memory>:4: the face uses vertex 2, but line 2 gives it only 2 of its 3 coordinates");
}

TEST(ObjFile, ManyBadLinesGiveOneWarningPerCauseInLinearTime) {
    std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    for (int i = 0; i < 100000; ++i) obj += "v nan 0 0\nmtllib \nusemtl m" + std::to_string(i) + "\n";
    const Model model = parse_obj(obj, "");
    EXPECT_EQ(
        model.warnings,
        (std::vector<std::string>{
            "<memory>:6: mtllib names no file (nor do 99999 more mtllib lines)",
            "<memory>:5: vertex 4 has 'nan', which is not a finite number; no face uses it (nor 99999 more such vertices)",
            "<memory>:7: material 'm0' is used, but the file names no material library (nor 99999 more materials the faces use); "
            "drawing the default material"}));
}

TEST(ObjFile, MapPathsWrittenTheWindowsWayWithQuotesOrAnotherLetterCaseAreFound) {
    const test_support::ScratchDir dir;
    std::filesystem::create_directories(dir / "Textures");
    const raster::Framebuffer red = test_support::checkerboard(1, 2, {200, 0, 0}, {200, 0, 0});
    test_support::write_png(dir / "wal67ar_small.jpg", red);  // named like the spider's; read by its content
    test_support::write_png(dir / "my texture.png", red);
    test_support::write_png(dir / "Textures" / "wood.png", red);
    test_support::write_png(dir / "Dup.png", red);
    test_support::write_png(dir / "dup.PNG", red);
    const std::vector<std::pair<std::string, bool>> maps{
        {".\\Wal67AR_Small.JPG", true}, {"\"my texture.png\"", true}, {"textures\\WOOD.png", true},
        {"./Textures/wood.png", true},  {"DUP.png", false},           {"nowhere\\wood.png", false}};
    for (const auto& [written, found] : maps) {
        test_support::write_text(dir / "spider.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd " + written + "\n");
        test_support::write_text(dir / "spider.obj", test_support::textured_cube_obj("spider.mtl", "skin"));
        const Model model = raster::read_obj(dir / "spider.obj");
        ASSERT_EQ(model.parts.size(), 1U);
        EXPECT_EQ(model.parts[0].texture != nullptr, found)
            << written << ": " << ::testing::PrintToString(model.warnings);
        EXPECT_EQ(model.warnings.size(), found ? 0U : 1U) << written;
    }
    // An MTL named the Windows way is found too.
    test_support::write_text(dir / "Textures" / "Spider.MTL", "newmtl skin\nKd 1 1 1\nmap_Kd ..\\my texture.png\n");
    test_support::write_text(dir / "windows.obj", test_support::textured_cube_obj("textures/spider.mtl", "skin"));
    const Model windows = raster::read_obj(dir / "windows.obj");
    EXPECT_NE(windows.parts.at(0).texture, nullptr) << ::testing::PrintToString(windows.warnings);
}
