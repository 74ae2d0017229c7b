// Every folder of Debian's assimp-testmodels: one model of each format read through the
// Open Asset Import Library, or refused in one line saying why (doc/conventions.md#model-formats).
#include <raster/io/model_file.hpp>

#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using test_support::ScratchDir;

namespace {

const std::filesystem::path kTestModels = "/usr/share/assimp/models";

// The line read_model refuses a file with, less the file's name; "" when it reads.
std::string refusal(const std::filesystem::path& path) {
    try {
        (void)raster::read_model(path);
    } catch (const std::runtime_error& problem) {
        const std::string what = problem.what(), prefix = path.string() + ": ";
        return what.starts_with(prefix) ? what.substr(prefix.size()) : what;
    }
    return "";
}

}  // namespace

TEST(ModelFormats, OneModelOfEveryFormatTheLinkedAssimpReadsIsDrawn) {
    if (!std::filesystem::exists(kTestModels / "OFF")) GTEST_SKIP() << "assimp-testmodels is not installed";
    for (const char* good : {"3D/box_a.3d",
                             "3DS/fels.3ds",
                             "3MF/box.3mf",
                             "AC/Wuson.ac",
                             "AMF/test1.amf",
                             "ASE/ThreeCubesGreen.ASE",
                             "B3D/WusonBlitz.b3d",
                             "BLEND/BlenderDefault_276.blend",
                             "BVH/01_01.bvh",
                             "COB/molecule.cob",
                             "Collada/duck.dae",
                             "DXF/wuson.dxf",
                             "FBX/box.fbx",
                             "HMP/terrain.hmp",
                             "IFC/AC14-FZK-Haus.ifc",
                             "IQM/mrfixit.iqm",
                             "LWO/LWO2/boxuv.lwo",
                             "LWS/move_x.lws",
                             "MD2/faerie.md2",
                             "MD5/SimpleCube.md5mesh",
                             "MDC/spider.mdc",
                             "MDL/MDL (HL1)/chrome_sphere.mdl",
                             "MS3D/Wuson.ms3d",
                             "NFF/NFF/dodecahedron.nff",
                             "OFF/Cube.off",
                             "OpenGEX/Example.ogex",
                             "Q3D/WusonOrange.q3o",
                             "RAW/Wuson.raw",
                             "SIB/heffalump.sib",
                             "SMD/triangle.smd",
                             "X/test_cube_text.x",
                             "X3D/HelloX3dTrademark.x3d",
                             "XGL/sample_official.xgl"}) {
        try {
            const raster::Model model = raster::read_model(kTestModels / good);
            EXPECT_GT(raster::triangle_count(model), 0U) << good;
        } catch (const std::runtime_error& problem) {
            ADD_FAILURE() << good << ": " << problem.what();
        }
    }
}

TEST(ModelFormats, FoldersItCannotReadAreRefusedSayingWhy) {
    if (!std::filesystem::exists(kTestModels / "OFF")) GTEST_SKIP() << "assimp-testmodels is not installed";
    const std::vector<std::pair<const char*, std::string>> refused{
        {"WRL/Wuson.wrl", "a VRML model: the Open Asset Import Library has no VRML reader; save it as X3D or glTF"},
        {"JT/conrod.jt", "a JT model, which the Open Asset Import Library raster is linked with does not read"},
        {"M3D/suzanne.m3d", "a Model 3D file, which the Open Asset Import Library raster is linked with does not read"},
        {"CSM/ThomasFechten.csm", "CharacterStudio motion without a model, which raster does not read"},
        {"Ogre/TheThing/Mesh.mesh.xml",
         "XML, which may be Collada, Irrlicht or Ogre: rename it .dae, .irr, .irrmesh or .mesh"},
        // Irrlicht's samples are UTF-16, which assimp 5.2.5's XML parser fails on too.
        {"IRRMesh/spider.irrmesh", "is UTF-16 text, which raster does not read: save it as UTF-8"},
        {"IRR/box.irr", "is UTF-16 text, which raster does not read: save it as UTF-8"},
        // assimp 5.2.5's own reader fails on this one.
        {"TER/RealisticTerrain.ter", "not a Terragen terrain model raster can read (or one it finds broken)"},
        {"glTF/BoxTextured-glTF/BoxTextured.gltf", "is glTF 1.0; raster reads glTF 2.0"},
    };
    for (const auto& [bad, why] : refused) EXPECT_EQ(refusal(kTestModels / bad), why) << bad;
}

TEST(ModelFormats, AFileWhoseSignatureIsAnotherFormatsIsRefusedBeforeAnyReaderSeesIt) {
    const ScratchDir dir;
    test_support::write_text(dir / "cube.fbx", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n");
    EXPECT_EQ(refusal(dir / "cube.fbx"), "looks like a PLY model, not an FBX model");
    test_support::write_text(dir / "cube.off", "\x89PNG\r\n");
    EXPECT_EQ(refusal(dir / "cube.off"), "looks like a PNG image, not an OFF model");
    test_support::write_text(dir / "cube.dae", "");
    EXPECT_EQ(refusal(dir / "cube.dae"), "is empty, not a Collada model");
    test_support::write_text(dir / "cube.usdz", "PK");
    EXPECT_EQ(refusal(dir / "cube.usdz"), "a USD scene, which raster does not read; save it as glTF");
    test_support::write_text(dir / "cube.xyz", "0 0 0\n");
    EXPECT_EQ(refusal(dir / "cube.xyz").rfind("raster reads models ending in .obj, .gltf, .glb, .stl, .ply, .3d,", 0),
              0U);
}

TEST(ModelFormats, AnOffModelWrittenByATestIsReadWithItsFaces) {
    const ScratchDir dir;
    test_support::write_text(dir / "triangle.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const raster::Model model = raster::read_model(dir / "triangle.off");
    EXPECT_EQ(raster::triangle_count(model), 1U);
    EXPECT_TRUE(raster::has_model_ending("A.DAE"));
    EXPECT_FALSE(raster::has_model_ending("a.png"));
}
