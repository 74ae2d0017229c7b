// Unlit shading reads the base colour map where its KHR_texture_transform moves it, as the lit
// shaders do (doc/conventions.md#texture-transform).
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>

#include "support/gltf_square.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace {

// The written square, its red and blue strip turned an eighth and repeated twice by the transform;
// matte, with white corner colours when `tinted`.
raster::Model turned_square(const std::filesystem::path& dir, bool tinted) {
    const std::string material = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
      "extensions": {"KHR_texture_transform": {"rotation": 0.7853982, "scale": [2, 2], "offset": [0.84, 0]}}},
      "metallicFactor": 0, "roughnessFactor": 1}})";
    const std::vector<float> white = tinted ? std::vector<float>(16, 1.0F) : std::vector<float>{};
    return raster::read_model(test_support::write_gltf_square(
        dir, material, R"( "extensionsUsed": ["KHR_texture_transform"],)", R"([{"mesh": 0}])", true, white));
}

// The square seen from +z filling an 8 x 8 picture, 'r' where red leads, 'b' where blue does, '-' the background.
std::vector<std::string> hue_rows(const raster::Model& model, raster::ShadingMethod shading) {
    raster::ModelView view;
    view.eye = glm::dvec3(0.0, 0.0, 4.0);
    view.target = glm::dvec3(0.0);
    view.orthographic = true;
    view.half_height = 0.9;
    view.shading = shading;
    raster::Framebuffer image(8, 8);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const raster::Model>(model), view, 8, 8)
        .render(image, depth, 0.0, {.samples = 1});
    std::vector<std::string> rows;
    for (int y = 0; y < 8; ++y) {
        std::string row;
        for (int x = 0; x < 8; ++x) {
            const raster::Rgb c = image.pixel(x, y);
            if (c == view.background) {
                row += '-';
                continue;
            }
            row += c.r > c.b + 8 ? 'r' : c.b > c.r + 8 ? 'b' : '.';
        }
        rows.push_back(row);
    }
    return rows;
}

std::string both(const std::vector<std::string>& expected, const std::vector<std::string>& drawn) {
    std::string text = "expected | drawn\n";
    for (std::size_t y = 0; y < expected.size(); ++y) text += expected[y] + " | " + drawn.at(y) + "\n";
    return text;
}

}  // namespace

TEST(UnlitTextureTransform, UnlitPlacesATransformedBaseColourMapAsTheLitShadersDo) {
    const test_support::ScratchDir dir;
    // Stripes across the diagonal where the lit shaders place them (pinned by GltfTextureTransform's tests).
    const std::vector<std::string> expected{
        "brrbbbrr", "rrbbbrrr", "rbbbrrrb", "bbbrrrbb", "bbrrrbbb", "brrrbbbr", "rrrbbbrr", "rrbbbrrb",
    };
    for (const bool tinted : {false, true}) {
        const raster::Model model = turned_square(dir.path(), tinted);
        ASSERT_EQ(model.parts.at(0).mesh.colours.empty(), !tinted);
        const std::vector<std::string> lit = hue_rows(model, raster::ShadingMethod::phong);
        const std::vector<std::string> unlit = hue_rows(model, raster::ShadingMethod::unlit);
        EXPECT_EQ(lit, expected) << "lit, tinted " << tinted << "\n" << both(expected, lit);
        EXPECT_EQ(unlit, expected) << "unlit, tinted " << tinted << "\n" << both(expected, unlit);
    }
}
