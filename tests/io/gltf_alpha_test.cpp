// glTF alphaMode, alphaCutoff and base colour alpha read through assimp (doc/conventions.md#transparency).
#include <raster/io/model.hpp>
#include <raster/io/model_file.hpp>

#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

// A glTF 2.0 triangle facing +z drawn with `material`, the JSON of its one material; the buffer
// holds the corners (-1, -1, 0), (1, -1, 0) and (0, 1, 0) as little-endian floats.
std::string triangle_with(const std::string& material) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}], "materials": [)" +
           material + R"(],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
  "buffers": [{"byteLength": 36,
               "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]}
)";
}

raster::Model read_with(const std::string& material) {
    const test_support::ScratchDir dir;
    test_support::write_text(dir / "triangle.gltf", triangle_with(material));
    return raster::read_model(dir / "triangle.gltf");
}

raster::Opacity opacity_with(const std::string& material, std::vector<std::string>* warnings = nullptr) {
    const raster::Model model = read_with(material);
    if (warnings != nullptr) *warnings = model.warnings;
    EXPECT_EQ(model.parts.size(), 1U);
    return model.parts.empty() ? raster::Opacity{} : model.parts[0].opacity;
}

}  // namespace

TEST(GltfAlpha, BlendTakesTheBaseColourAlpha) {
    const raster::Opacity blend =
        opacity_with(R"({"alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1, 0, 0, 0.25]}})");
    EXPECT_EQ(blend.mode, raster::AlphaMode::blend);
    EXPECT_EQ(blend.factor, 0.25F);
}

TEST(GltfAlpha, MaskTakesItsCutoffAndOpaqueIgnoresAlpha) {
    const raster::Opacity mask = opacity_with(
        R"({"alphaMode": "MASK", "alphaCutoff": 0.75, "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.5]}})");
    EXPECT_EQ(mask.mode, raster::AlphaMode::mask);
    EXPECT_EQ(mask.cutoff, 0.75F);
    EXPECT_EQ(mask.factor, 0.5F);
    EXPECT_EQ(opacity_with(R"({"alphaMode": "MASK"})").cutoff, 0.5F);  // the specification's default
    EXPECT_EQ(opacity_with(R"({"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.5]}})").mode,
              raster::AlphaMode::opaque);
}

TEST(GltfAlpha, CutoffOutsideZeroToOneIsClampedWithAWarning) {
    std::vector<std::string> warnings;
    const raster::Opacity mask = opacity_with(R"({"alphaMode": "MASK", "alphaCutoff": 2})", &warnings);
    EXPECT_EQ(mask.cutoff, 1.0F);
    bool named = false;
    for (const std::string& w : warnings) named = named || w.find("has alphaCutoff 2") != std::string::npos;
    EXPECT_TRUE(named) << testing::PrintToString(warnings);
}
