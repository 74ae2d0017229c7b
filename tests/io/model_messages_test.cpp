// What a model carries that raster does not draw is one warning; files it cannot read are one
// line in their own words (doc/conventions.md#not-drawn).
#include <raster/io/model_file.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using test_support::ScratchDir;
using test_support::write_text;

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

const std::string kPlyHeader = "ply\nformat binary_little_endian 1.0\nelement vertex ";
const std::string kXyz = "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";

}  // namespace

TEST(ModelMessages, AUtf16ObjIsAskedToBeSavedAsUtf8) {
    const ScratchDir dir;
    const std::string utf16("\xFF\xFEv\0 \0"
                            "0\0\n\0",
                            10);
    write_text(dir / "wide.obj", utf16);
    EXPECT_EQ(refusal(dir / "wide.obj"), "is UTF-16 text, which raster does not read: save it as UTF-8");
    if (std::filesystem::exists(kTestModels / "OBJ/box_UTF16BE.obj")) {
        EXPECT_EQ(refusal(kTestModels / "OBJ/box_UTF16BE.obj"),
                  "is UTF-16 text, which raster does not read: save it as UTF-8");
    }
}

TEST(ModelMessages, APlyCutShortAndAValidEmptyPlyAreToldApart) {
    const ScratchDir dir;
    const std::string cut_here = " bytes left can hold: the file is cut short, or its header is wrong";
    write_text(dir / "cut.ply", kPlyHeader + "3" + kXyz + std::string(30, '\0'));
    EXPECT_EQ(refusal(dir / "cut.ply"), "the PLY header declares 3 'vertex' elements, more than the 30" + cut_here);
    // Text long enough for the count, but a line short: assimp's reader is left to say, in raster's words.
    write_text(dir / "cut-text.ply", "ply\nformat ascii 1.0\nelement vertex 3" + kXyz + "0.00 0.00 0.00\n1.00 0 0\n");
    const std::string cut_text =
        "the PLY data is cut short: its header declares 3 'vertex' elements and the data ends in element 3";
    const std::string why = refusal(dir / "cut-text.ply");
    if (why.empty()) {
        EXPECT_EQ(
            raster::read_model(dir / "cut-text.ply").warnings,
            std::vector<std::string>{(dir / "cut-text.ply").string() + ": " + cut_text + "; drawing what is there"});
    } else {
        EXPECT_EQ(why, cut_text);
    }
    write_text(dir / "empty.ply", kPlyHeader + "0" + kXyz);
    EXPECT_EQ(refusal(dir / "empty.ply"),
              "nothing to draw: no faces, points or lines (its header declares no vertices)");
}

TEST(ModelMessages, APlyClaimingABillionPointsIsRefusedBeforeAnythingIsAllocatedByTheClaim) {
    const ScratchDir dir;
    // 12 bytes a point: 100 million points need more than the 100 million bytes there are.
    write_text(dir / "binary.ply", kPlyHeader + "1000000000" + kXyz + std::string(1000, '\0'));
    EXPECT_EQ(refusal(dir / "binary.ply"), "the PLY header declares 1000000000 'vertex' elements, more than the 1000"
                                           " bytes left can hold: the file is cut short, or its header is wrong");
    write_text(dir / "ascii.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000" + kXyz + "0 0 0\n");
    EXPECT_EQ(refusal(dir / "ascii.ply"), "the PLY header declares 1000000000 'vertex' elements, more than the 6"
                                          " bytes left can hold: the file is cut short, or its header is wrong");
    write_text(dir / "dense.ply", kPlyHeader + "100" + kXyz + std::string(1199, '\0'));
    EXPECT_EQ(refusal(dir / "dense.ply"),
              "the PLY header declares 100 'vertex' elements, more than the 1199 bytes left can hold: "
              "the file is cut short, or its header is wrong");
}

TEST(ModelMessages, SkinsAndAnimationsAreOneWarningNamingThemAndGltfCamerasAreCarried) {
    if (!std::filesystem::exists(kTestModels / "glTF2/simple_skin/simple_skin.gltf"))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    const std::filesystem::path skin = kTestModels / "glTF2/simple_skin/simple_skin.gltf";
    EXPECT_EQ(raster::read_model(skin).warnings,
              std::vector<std::string>{skin.string() +
                                       ": it carries a skin (drawn in its rest pose) and 1 animation (not played)"});
    const std::filesystem::path cameras = kTestModels / "glTF2/cameras/Cameras.gltf";
    const raster::Model carrying = raster::read_model(cameras);  // render --camera N draws from one
    EXPECT_EQ(carrying.warnings, std::vector<std::string>{});
    EXPECT_EQ(carrying.cameras.size(), 2U);
}

TEST(ModelMessages, GltfExtensionsRasterDoesNotDrawAreOneWarningAndThoseItDrawsNone) {
    const ScratchDir dir;
    std::string gltf = test_support::gltf_two_squares();
    gltf.insert(gltf.find('{') + 1, R"("extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform", )"
                                    R"("KHR_materials_emissive_strength", "KHR_materials_clearcoat"], )");
    write_text(dir / "squares.gltf", gltf);
    EXPECT_EQ(raster::read_model(dir / "squares.gltf").warnings,
              std::vector<std::string>{(dir / "squares.gltf").string() +
                                       ": glTF extensions raster does not draw: KHR_lights_punctual, "
                                       "KHR_materials_clearcoat; drawn without them"});
}
