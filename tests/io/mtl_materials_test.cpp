// MTL's maps beyond map_Kd and its physically based fields (doc/conventions.md#mtl-maps,
// doc/conventions.md#mtl-pbr), read from files the tests write.
#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>
#include <raster/shade/mapped_phong_shader.hpp>
#include <raster/shade/metallic_roughness_lighting.hpp>

#include "io/derived_maps.hpp"
#include "io/model_wire.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

using raster::Model;
using raster::Rgb;
using test_support::ScratchDir;

namespace {

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
    for (const std::string& line : lines) {
        if (line.find(text) != std::string::npos) return true;
    }
    return false;
}

// A cube of material "m" from `mtl`, with each image written as a PNG beside it.
Model cube(const ScratchDir& dir, const std::string& mtl,
           const std::vector<std::pair<std::string, raster::Framebuffer>>& images = {}) {
    for (const auto& [name, image] : images) test_support::write_png(dir / name, image);
    test_support::write_text(dir / "m.mtl", "newmtl m\n" + mtl);
    test_support::write_text(dir / "m.obj", test_support::textured_cube_obj("m.mtl", "m"));
    return raster::read_obj(dir / "m.obj");
}

raster::Framebuffer texel(Rgb colour) { return raster::Framebuffer(1, 1, {colour.r, colour.g, colour.b}); }

// The colour a Phong part shows at a point facing the viewer and a light head-on (intensity 0: no light).
Rgb shown(const raster::ModelPart& part, float light) {
    const std::array<raster::DirectionalLight, 1> lights{{{{0.0F, 0.0F, 1.0F}, light}}};
    const raster::LinearLighting lighting(part.material, lights, {}, {0.0F, 0.0F, 1.0F});
    const raster::MappedPhongSmoothShader shader{
        &lighting, {part.material.diffuse, part.texture.get(), part.sampler}, &part.phong_maps};
    const raster::MappedPhongSmoothShader::Varying at{{0, 0, 0}, {0, 0, 1}, {0.5F, 0.5F}, {1, 1, 1}};
    const raster::MappedPhongSmoothShader::Varying still{};
    return shader.pixel(at, still, still);
}

}  // namespace

TEST(MtlMaps, GlowMapMultipliesKe) {
    const ScratchDir dir;
    const Model model = cube(dir, "Kd 0 0 0\nKe 1 1 1\nmap_Ke glow.png\n", {{"glow.png", texel({0, 255, 0})}});
    ASSERT_EQ(model.parts.size(), 1U);
    const raster::ModelPart& part = model.parts[0];
    EXPECT_FALSE(part.metallic_roughness.has_value()) << "Ke and map_Ke alone stay Blinn-Phong";
    ASSERT_TRUE(part.phong_maps.emissive);
    EXPECT_EQ(part.material.emissive, (raster::LinearRgb{1, 1, 1}));
    EXPECT_EQ(shown(part, 0.0F), (Rgb{0, 255, 0}));  // not white: the map times its factor
    EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
}

TEST(MtlMaps, SpecularMapMultipliesKs) {
    const ScratchDir dir;
    const Model model =
        cube(dir, "Kd 0 0 0\nKs 0.6 0.6 0.6\nNs 10\nmap_Ks spec.png\n", {{"spec.png", texel({255, 0, 0})}});
    const raster::ModelPart& part = model.parts.at(0);
    ASSERT_TRUE(part.phong_maps.specular);
    const Rgb highlight = shown(part, 1.0F);
    EXPECT_EQ(highlight, raster::srgb_from_linear({0.6F, 0.0F, 0.0F}));  // Ks 0.6 times the map's red
    const Model black =
        cube(dir, "Kd 0 0 0\nKs 0.6 0.6 0.6\nNs 10\nmap_Ks spec.png\n", {{"spec.png", texel({0, 0, 0})}});
    EXPECT_EQ(shown(black.parts.at(0), 1.0F), (Rgb{0, 0, 0}));  // no grey smear where the map is black
}

TEST(MtlMaps, AMapThatCannotBeReadWarnsOnceAndLeavesItsFactor) {
    const ScratchDir dir;
    const Model model = cube(dir, "Kd 0 0 0\nKe 0.5 0.5 0.5\nmap_Ke lost.png\nmap_Ks lost.png\n");
    const raster::ModelPart& part = model.parts.at(0);
    EXPECT_FALSE(part.phong_maps.any());
    EXPECT_EQ(part.material.emissive, (raster::LinearRgb{0.5F, 0.5F, 0.5F}));
    ASSERT_EQ(model.warnings.size(), 1U) << ::testing::PrintToString(model.warnings);  // one file, read once
    EXPECT_TRUE(mentions(model.warnings, "lost.png")) << model.warnings[0];
}

TEST(MtlMaps, PhongMapsCrossToTheReaderProcessAndBack) {
    const ScratchDir dir;
    const Model model = cube(dir, "Ks 1 1 1\nNs 8\nmap_Ks s.png\nmap_Ke e.png\nbump b.png\n",
                             {{"s.png", texel({1, 2, 3})}, {"e.png", texel({4, 5, 6})}, {"b.png", texel({7, 8, 9})}});
    std::vector<std::uint8_t> wire;
    raster::detail::append_model_wire(model, wire);
    const Model carried = raster::detail::model_from_wire(wire);
    const raster::PhongMaps& maps = carried.parts.at(0).phong_maps;
    ASSERT_TRUE(maps.specular && maps.emissive && maps.normal);
    EXPECT_EQ(maps.specular->level(0), model.parts[0].phong_maps.specular->level(0));
    EXPECT_EQ(maps.emissive->level(0), model.parts[0].phong_maps.emissive->level(0));
    EXPECT_EQ(maps.normal->encoding(), raster::TexelEncoding::linear);
}

TEST(MtlBump, HeightMapBecomesNormals) {
    // Heights rising to the right (u) lean the normal left; a flat row stays straight up.
    const raster::Texture ramp(raster::Framebuffer(3, 1, {0, 0, 0, 100, 100, 100, 200, 200, 200}));
    const raster::Texture normals = raster::detail::normals_from_heights(ramp, 'l', 1.0F, raster::TextureWrap::clamp);
    EXPECT_EQ(normals.encoding(), raster::TexelEncoding::linear);
    const auto bytes = normals.level(0).bytes();
    // Middle texel: slope (200 - 0) / 255 / 2 = 0.392 per texel: (-0.365, 0, 0.931).
    EXPECT_EQ(bytes[3], 81);
    EXPECT_EQ(bytes[4], 128);
    EXPECT_EQ(bytes[5], 246);
    const raster::Texture doubled = raster::detail::normals_from_heights(ramp, 'l', 2.0F, raster::TextureWrap::clamp);
    EXPECT_LT(doubled.level(0).bytes()[3], 81) << "-bm scales the heights";
    const ScratchDir dir;
    const Model model = cube(dir, "Kd 1 1 1\nbump -bm 2 b.png\n",
                             {{"b.png", raster::Framebuffer(3, 1, {0, 0, 0, 100, 100, 100, 200, 200, 200})}});
    ASSERT_TRUE(model.parts.at(0).phong_maps.normal);
    EXPECT_FALSE(model.parts[0].metallic_roughness.has_value()) << "a bump map alone stays Blinn-Phong";
    EXPECT_EQ(model.parts[0].phong_maps.normal->level(0).bytes()[3], doubled.level(0).bytes()[3]);
}

TEST(MtlPbr, PhysicallyBasedFieldsMakeAMetallicRoughnessMaterial) {
    const Model model = raster::parse_obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl gold\nf 1 2 3\n",
                                          "newmtl gold\nKd 1 0.8 0.3\nKe 0 0.5 0\nPr 0.25\nPm 1\nd 0.5\n");
    ASSERT_TRUE(model.parts.at(0).metallic_roughness.has_value());
    const raster::MetallicRoughness& m = *model.parts[0].metallic_roughness;
    EXPECT_EQ(m.base_colour, (raster::LinearRgb{1.0F, 0.8F, 0.3F}));
    EXPECT_EQ(m.emissive, (raster::LinearRgb{0.0F, 0.5F, 0.0F}));
    EXPECT_EQ(m.roughness, 0.25F);
    EXPECT_EQ(m.metallic, 1.0F);
    EXPECT_EQ(model.parts[0].opacity.factor, 0.5F);
    // Pr 0 alone is still a physically based field; Ke alone is not.
    const auto pbr = [](const std::string& mtl) {
        return raster::parse_obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n", "newmtl a\n" + mtl)
            .parts.at(0)
            .metallic_roughness.has_value();
    };
    EXPECT_TRUE(pbr("Pr 0\n"));
    EXPECT_TRUE(pbr("  Pm\t0\n"));
    EXPECT_FALSE(pbr("Ke 1 1 1\nKs 0.5 0.5 0.5\n"));
    EXPECT_FALSE(pbr("Pra 1\n"));
}

TEST(MtlPbr, WithoutPrRoughnessComesFromNsAsBlenderReadsIt) {
    const Model model =
        raster::parse_obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n", "newmtl a\nNs 250\nPm 0.5\n");
    ASSERT_TRUE(model.parts.at(0).metallic_roughness.has_value());
    EXPECT_FLOAT_EQ(model.parts[0].metallic_roughness->roughness, 0.5F);  // 1 - sqrt(250 / 1000)
}

TEST(MtlPbr, PrAndPmOutsideZeroToOneAreClampedWithAWarning) {
    const Model model =
        raster::parse_obj("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n", "newmtl a\nPr 2\nPm -1e39\n");
    ASSERT_TRUE(model.parts.at(0).metallic_roughness.has_value());
    EXPECT_EQ(model.parts[0].metallic_roughness->roughness, 1.0F);
    EXPECT_EQ(model.parts[0].metallic_roughness->metallic, 1.0F) << "not finite takes 1, as glTF's NaN";
    ASSERT_EQ(model.warnings.size(), 2U) << ::testing::PrintToString(model.warnings);
    EXPECT_TRUE(mentions(model.warnings, "material 'a' has Pr 2")) << model.warnings[0];
    EXPECT_TRUE(mentions(model.warnings, "material 'a' has Pm -inf")) << model.warnings[1];
}

TEST(MtlPbr, RoughnessAndMetallicMapsMultiplyTheirFactors) {
    const ScratchDir dir;
    // map_Pr is 2 x 1 (left 51, right 255), map_Pm one texel of 102: combined at 2 x 1.
    const Model model = cube(dir, "Pr 0.5\nPm 1\nmap_Pr r.png\nmap_Pm m.png\nnorm -bm 0.5 n.png\nmap_Ke e.png\n",
                             {{"r.png", raster::Framebuffer(2, 1, {51, 51, 51, 255, 255, 255})},
                              {"m.png", texel({102, 102, 102})},
                              {"n.png", texel({128, 128, 255})},
                              {"e.png", texel({0, 0, 255})}});
    ASSERT_TRUE(model.parts.at(0).metallic_roughness.has_value());
    const raster::MetallicRoughness& m = *model.parts[0].metallic_roughness;
    ASSERT_TRUE(m.metallic_roughness_map && m.normal_map && m.emissive_map);
    EXPECT_EQ(m.metallic_roughness_map->encoding(), raster::TexelEncoding::linear);
    EXPECT_EQ(m.normal_map->encoding(), raster::TexelEncoding::linear);
    EXPECT_EQ(m.emissive_map->encoding(), raster::TexelEncoding::srgb);
    EXPECT_EQ(m.normal_scale, 0.5F);
    const raster::MetallicRoughnessLighting lighting(m, {raster::TextureFilter::nearest}, nullptr, {}, {}, {0, 0, 1});
    raster::MaterialPoint left{{0, 0, 0}, {0, 0, 1}, {0.25F, 0.5F}};
    EXPECT_NEAR(lighting.sample(left).roughness, 0.5F * 0.2F, 1e-6F);
    EXPECT_NEAR(lighting.sample(left).metallic, 1.0F * 0.4F, 1e-6F);
    raster::MaterialPoint right{{0, 0, 0}, {0, 0, 1}, {0.75F, 0.5F}};
    EXPECT_NEAR(lighting.sample(right).roughness, 0.5F, 1e-6F);
    EXPECT_TRUE(model.warnings.empty()) << model.warnings.front();
}

TEST(MtlPbr, ThinRoughnessAndMetallicMapsCombineAtTheSizeOfTheOneWithMoreTexels) {
    const ScratchDir dir;
    // 4 x 1 and 1 x 3: a 4 x 3 map would hold more than either; the combined one is 4 x 1.
    const std::vector<std::uint8_t> wide(4 * 3, 51), tall(3 * 3, 102);
    const Model model = cube(dir, "Pr 1\nPm 1\nmap_Pr r.png\nmap_Pm m.png\n",
                             {{"r.png", raster::Framebuffer(4, 1, wide)}, {"m.png", raster::Framebuffer(1, 3, tall)}});
    ASSERT_TRUE(model.parts.at(0).metallic_roughness.has_value());
    const auto& map = model.parts[0].metallic_roughness->metallic_roughness_map;
    ASSERT_TRUE(map);
    EXPECT_EQ(map->width(), 4);
    EXPECT_EQ(map->height(), 1);
}

TEST(MtlPbr, AMissingRoughnessMapWarnsAndLeavesPrAlone) {
    const ScratchDir dir;
    const Model model = cube(dir, "Pr 0.5\nmap_Pr gone.png\n");
    ASSERT_TRUE(model.parts.at(0).metallic_roughness.has_value());
    EXPECT_FALSE(model.parts[0].metallic_roughness->metallic_roughness_map);
    EXPECT_EQ(model.parts[0].metallic_roughness->roughness, 0.5F);
    ASSERT_EQ(model.warnings.size(), 1U);
    EXPECT_TRUE(mentions(model.warnings, "gone.png")) << model.warnings[0];
    EXPECT_TRUE(mentions(model.warnings, "with Pr alone")) << model.warnings[0];
}
