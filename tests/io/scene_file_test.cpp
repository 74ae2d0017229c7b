// glTF 2.0, STL and PLY through the Open Asset Import Library: files the tests write, and the real
// and broken files of Debian's assimp-testmodels.
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/samples.hpp>

#include "support/golden.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

using raster::Framebuffer;
using raster::Model;
using test_support::kRender;
using test_support::run;
using test_support::ScratchDir;

namespace {

const std::filesystem::path kTestModels = "/usr/share/assimp/models";

Framebuffer drawn(const Model& model, raster::ModelView view = {}) {
    Framebuffer image(160, 120);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const Model>(model), view, image.width(), image.height())
        .render(image, depth, 0.0, {.samples = raster::kSmoothSamples});
    return image;
}

std::string refusal(const std::filesystem::path& path) {
    try {
        (void)raster::read_model(path);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(SceneFile, GltfNodesPlaceTheirMeshesThroughTheWholeHierarchy) {
    const ScratchDir dir;
    test_support::write_text(dir / "squares.gltf", test_support::gltf_two_squares());
    const Model model = raster::read_model(dir / "squares.gltf");
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_EQ(raster::triangle_count(model), 4U);
    // The second square: turned 45 degrees, halved, 1.3 right and (from the parent) 0.5 up.
    const raster::Bounds bounds = raster::bounds_of(model);
    EXPECT_NEAR(bounds.high.x, 1.3 + 0.5 * std::sqrt(2.0), 1e-5);
    EXPECT_NEAR(bounds.low.x, -2.3, 1e-5);
    EXPECT_NEAR(bounds.high.y, 1.5, 1e-5);
    // Base colour (linear) as the diffuse colour; roughness 0.5 gives a highlight.
    EXPECT_NEAR(model.parts[0].material.diffuse.r, 0.8F, 1e-6F);
    EXPECT_NEAR(model.parts[0].material.diffuse.g, 0.2F, 1e-6F);
    EXPECT_TRUE(model.parts[0].material.shininess.has_value());
    raster::ModelView front;
    front.eye = glm::dvec3(0.0, 0.5, 6.0);
    EXPECT_TRUE(test_support::matches_snapshot(drawn(model, front), "models/format-gltf"));
}

TEST(SceneFile, StlInAsciiAndBinaryAndPlyWithAQuadFaceDraw) {
    const ScratchDir dir;
    test_support::write_text(dir / "ascii.stl", test_support::stl_tetrahedron_ascii());
    test_support::write_text(dir / "binary.STL", test_support::stl_tetrahedron_binary());
    test_support::write_text(dir / "pyramid.ply", test_support::ply_pyramid());
    const Model ascii = raster::read_model(dir / "ascii.stl");
    EXPECT_EQ(raster::triangle_count(ascii), 4U);
    EXPECT_EQ(raster::open_parts(ascii), (std::vector<bool>{false}));  // closed: culled as before
    const Framebuffer tetrahedron = drawn(ascii);
    const std::string text = test_support::stl_tetrahedron_ascii();
    const Model in_memory = raster::parse_scene_file(std::vector<std::uint8_t>(text.begin(), text.end()), "stl");
    EXPECT_EQ(drawn(in_memory), tetrahedron);
    EXPECT_EQ(drawn(raster::read_model(dir / "binary.STL")), tetrahedron);
    EXPECT_TRUE(test_support::matches_snapshot(tetrahedron, "models/format-stl"));
    const Model pyramid = raster::read_model(dir / "pyramid.ply");
    EXPECT_EQ(raster::triangle_count(pyramid), 6U);  // the quad base in two
    EXPECT_TRUE(test_support::matches_snapshot(drawn(pyramid), "models/format-ply"));
}

TEST(SceneFile, PlyAndStlColoursAreSrgbAndGltfColoursLinear) {
    const ScratchDir dir;
    const auto colours_of = [](const Model& model) {
        std::vector<raster::LinearRgb> all;
        for (const auto& part : model.parts) all.insert(all.end(), part.mesh.colours.begin(), part.mesh.colours.end());
        return all;
    };
    // PLY bytes are sRGB: 255 is 1, 0 is 0 (the pyramid's red, green, blue, yellow and white corners).
    test_support::write_text(dir / "pyramid.ply", test_support::ply_pyramid());
    const Model pyramid = raster::read_model(dir / "pyramid.ply");
    ASSERT_EQ(colours_of(pyramid).size(), pyramid.parts[0].mesh.positions.size());
    std::set<std::tuple<float, float, float>> seen;
    for (const raster::LinearRgb& c : colours_of(pyramid)) seen.insert({c.r, c.g, c.b});
    EXPECT_EQ(seen, (std::set<std::tuple<float, float, float>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 1, 1}}));
    // A mid grey byte in PLY is sRGB 128/255, linear 0.216.
    test_support::write_text(
        dir / "grey.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n0 0 0 128 128 128\n1 0 0 128 128 128\n"
        "0 1 0 128 128 128\n3 0 1 2\n");
    const std::vector<raster::LinearRgb> mid_grey = colours_of(raster::read_model(dir / "grey.ply"));
    ASSERT_EQ(mid_grey.size(), 3U);
    for (const raster::LinearRgb& c : mid_grey) {
        EXPECT_NEAR(c.r, raster::linear_from_srgb_channel(128.0 / 255.0), 1e-5);
    }
    // glTF's COLOR_0 is linear already: 0.5 stays 0.5.
    test_support::write_text(dir / "triangle.gltf", test_support::gltf_coloured_triangle(0.5F, 0.25F, 1.0F));
    const std::vector<raster::LinearRgb> gltf = colours_of(raster::read_model(dir / "triangle.gltf"));
    ASSERT_FALSE(gltf.empty());
    for (const raster::LinearRgb& c : gltf) EXPECT_EQ(c, (raster::LinearRgb{0.5F, 0.25F, 1.0F}));
    // Binary STL: a facet's 5-bit channels with bit 15 set, sRGB like PLY's; one facet full red,
    // one at 16/31 of green, two without a colour, which take assimp's default grey 0.6.
    const auto visible = [](unsigned r, unsigned g, unsigned b) {
        return static_cast<std::uint16_t>(0x8000U | r << 10U | g << 5U | b);
    };
    test_support::write_text(dir / "coloured.stl",
                             test_support::stl_tetrahedron_binary({visible(31, 0, 0), visible(0, 16, 0), 0, 0}));
    std::set<std::tuple<int, int, int>> stl;  // in thousandths
    for (const raster::LinearRgb& c : colours_of(raster::read_model(dir / "coloured.stl"))) {
        stl.insert({std::lround(c.r * 1000), std::lround(c.g * 1000), std::lround(c.b * 1000)});
    }
    const auto grey = static_cast<int>(std::lround(raster::linear_from_srgb_channel(0.6) * 1000));
    const auto green = static_cast<int>(std::lround(raster::linear_from_srgb_channel(16.0 / 31.0) * 1000));
    EXPECT_EQ(stl, (std::set<std::tuple<int, int, int>>{{1000, 0, 0}, {0, green, 0}, {grey, grey, grey}}));
    // An STL without colours has none, and draws its material as before.
    test_support::write_text(dir / "plain.stl", test_support::stl_tetrahedron_binary());
    EXPECT_TRUE(colours_of(raster::read_model(dir / "plain.stl")).empty());
    // assimp-testmodels' float-color.ply: one triangle of float colours, pure blue.
    if (std::filesystem::exists(kTestModels / "PLY/float-color.ply")) {
        const std::vector<raster::LinearRgb> blue = colours_of(raster::read_model(kTestModels / "PLY/float-color.ply"));
        ASSERT_EQ(blue.size(), 3U);
        for (const raster::LinearRgb& c : blue) {
            EXPECT_EQ(c, (raster::LinearRgb{0, 0, 1}));
        }
    }
}

TEST(SceneFile, EveryFileItOpensIsAnInputNoOutputMayReplace) {
    if (!std::filesystem::exists(kTestModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf"))
        GTEST_SKIP() << "assimp-testmodels is not installed";
    const ScratchDir dir;
    for (const char* name : {"BoxTextured.gltf", "BoxTextured0.bin", "CesiumLogoFlat.png"}) {
        std::filesystem::copy_file(kTestModels / "glTF2/BoxTextured-glTF" / name, dir / name);
    }
    const Model model = raster::read_model(dir / "BoxTextured.gltf");
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_NE(model.parts[0].texture, nullptr);
    for (const char* output : {"BoxTextured0.bin", "CesiumLogoFlat.png"}) {
        const auto result = run(kRender, {"BoxTextured.gltf", output}, dir.path());
        EXPECT_EQ(result.exit_code, 1) << output;
        EXPECT_NE(result.err.find("this run reads; choose another output name"), std::string::npos) << result.err;
    }
}

TEST(SceneFile, AssimpsTestModelsDrawAndItsBrokenOnesAreOneLine) {
    if (!std::filesystem::exists(kTestModels / "glTF2")) GTEST_SKIP() << "assimp-testmodels is not installed";
    for (const char* good :
         {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
          "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
          "STL/Spider_ascii.stl", "STL/Spider_binary.stl", "STL/Wuson.stl", "PLY/Wuson.ply", "PLY/cube_binary.ply",
          "PLY/float-color.ply"}) {
        EXPECT_EQ(refusal(kTestModels / good), "") << good;
    }
    const Framebuffer box = drawn(raster::read_model(kTestModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf"));
    EXPECT_EQ(drawn(raster::read_model(kTestModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb")), box);
    EXPECT_EQ(drawn(raster::read_model(kTestModels / "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf")), box);
    for (const char* bad :
         {"glTF2/MissingBin/BoxTextured.gltf", "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
          "glTF2/RecursiveNodes/RecursiveNodes.gltf", "glTF2/wrongTypes/badNumber.gltf",
          "glTF2/wrongTypes/badArray.gltf", "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf",
          "glTF2/TestNoRootNode/NoScene.gltf", "invalid/empty.ply", "invalid/empty.x"}) {
        const std::string message = refusal(kTestModels / bad);
        EXPECT_EQ(message.rfind((kTestModels / bad).string() + ": ", 0), 0U) << bad << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_EQ(refusal(kTestModels / "glTF2/MissingBin/BoxTextured.gltf"),
              (kTestModels / "glTF2/MissingBin/BoxTextured.gltf").string() + ": '" +
                  (kTestModels / "glTF2/MissingBin/BoxTextured0.bin").string() + "' does not exist");
}
