// glTF's metallic-roughness BRDF, its split-sum table and prefiltered surroundings, and the
// material read at a point: factors, maps, the normal map's frame and bad values.
#include <raster/shade/gltf_brdf.hpp>
#include <raster/shade/metallic_roughness.hpp>
#include <raster/shade/metallic_roughness_lighting.hpp>
#include <raster/shade/surroundings.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <gtest/gtest.h>

using raster::LinearRgb;
using raster::MaterialPoint;
using raster::MetallicRoughness;
using raster::MetallicRoughnessLighting;
using raster::Surroundings;

namespace {

constexpr float kPi = raster::gltf_brdf::kPi;
constexpr glm::vec3 kNormal{0.0F, 0.0F, 1.0F};

// The BRDF's reflectance under uniform white light, integrated on a grid of half vectors crowded
// toward the normal (theta_h = t^2 pi / 2, dl = 4 v.h dh), fine enough for sharp lobes: the
// reference the split sum must meet.
float furnace_reference(LinearRgb base, float metallic, float roughness, float n_dot_v) {
    const glm::vec3 v(std::sqrt(1.0F - n_dot_v * n_dot_v), 0.0F, n_dot_v);
    constexpr int kRings = 1200, kSpokes = 240;
    double sum = 0.0;
    for (int i = 0; i < kRings; ++i) {
        const double t = (i + 0.5) / kRings, theta = t * t * kPi / 2.0, d_theta = t * kPi / kRings;
        for (int j = 0; j < kSpokes; ++j) {
            const double phi = (j + 0.5) / kSpokes * 2.0 * kPi;
            const glm::vec3 h(static_cast<float>(std::sin(theta) * std::cos(phi)),
                              static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
            const float v_dot_h = glm::dot(v, h);
            if (!(v_dot_h > 0.0F)) continue;
            const glm::vec3 l = 2.0F * v_dot_h * h - v;
            if (!(l.z > 0.0F)) continue;
            const double f = raster::gltf_brdf::brdf(base, metallic, roughness, kNormal, v, glm::normalize(l)).r;
            sum += f * l.z * 4.0 * v_dot_h * std::sin(theta) * d_theta * (2.0 * kPi / kSpokes);
        }
    }
    return static_cast<float>(sum);
}

Surroundings uniform(float level) {
    return Surroundings([level](glm::vec3) { return LinearRgb{level, level, level}; });
}

MaterialPoint facing(glm::vec3 normal) { return {{0.0F, 0.0F, 0.0F}, normal}; }

std::shared_ptr<const raster::Texture> one_texel(std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                                 raster::TexelEncoding encoding) {
    return std::make_shared<const raster::Texture>(raster::Framebuffer(1, 1, {r, g, b}), encoding);
}

}  // namespace

// doc/conventions.md#surroundings: the white furnace, within 1 % of the energy received.
TEST(MetallicRoughness, WhiteFurnaceMatchesTheIntegratedBrdfWithinOnePercent) {
    const Surroundings white = uniform(1.0F);
    for (const float roughness : {1.0F, 0.5F, 0.2F}) {
        for (const float metallic : {0.0F, 1.0F}) {
            for (const float n_dot_v : {0.9F, 0.5F, 0.2F}) {
                MetallicRoughness m;
                m.metallic = metallic, m.roughness = roughness;
                const MetallicRoughnessLighting lighting(m, {}, &white, {}, {},
                                                         {std::sqrt(1 - n_dot_v * n_dot_v), 0, n_dot_v});
                const float ours = lighting.shade(facing(kNormal)).r;
                const float reference = furnace_reference({1, 1, 1}, metallic, roughness, n_dot_v);
                EXPECT_NEAR(ours, reference, 0.01F)
                    << "roughness " << roughness << " metallic " << metallic << " n.v " << n_dot_v;
            }
        }
    }
}

// The single-scattering model loses energy at roughness: a white rough dielectric keeps most,
// not all, of what it receives.
TEST(MetallicRoughness, WhiteRoughDielectricReflectsMostOfUniformLight) {
    const float reflected = furnace_reference({1, 1, 1}, 0.0F, 1.0F, 0.7F);
    EXPECT_GT(reflected, 0.9F);
    EXPECT_LT(reflected, 1.0F);
}

TEST(Surroundings, UniformLightComesBackUnchangedAtEveryRoughness) {
    const Surroundings grey = uniform(0.25F);
    for (const glm::vec3 d : {glm::vec3(0, 1, 0), glm::vec3(0.6F, -0.8F, 0), glm::vec3(0, 0, -1)}) {
        EXPECT_NEAR(grey.diffuse(d).g, 0.25F, 0.002F);
        for (const float roughness : {0.0F, 0.3F, 0.7F, 1.0F}) EXPECT_NEAR(grey.specular(d, roughness).g, 0.25F, 1e-4F);
    }
}

TEST(Surroundings, StudioIsBrighterAboveThanBelowAndGreyThroughout) {
    const Surroundings studio = Surroundings::studio();
    const LinearRgb up = studio.diffuse({0, 1, 0}), down = studio.diffuse({0, -1, 0});
    EXPECT_GT(up.r, 2.0F * down.r);
    EXPECT_GT(down.r, 0.0F);
    EXPECT_EQ(up.r, up.g);
    EXPECT_EQ(up.g, up.b);
}

// The specification's default material (white metal, rough) is grey in the studio, not black.
TEST(MetallicRoughness, DefaultMaterialShowsGreyInTheStudio) {
    const Surroundings studio = Surroundings::studio();
    const MetallicRoughnessLighting lighting(MetallicRoughness{}, {}, &studio, {}, {}, {0, 0, -1});
    const LinearRgb seen = lighting.shade(facing({0, 0, -1}));
    EXPECT_GT(seen.r, 0.1F);  // about 107 of 255 in sRGB, facing the horizon
    EXPECT_EQ(seen.r, seen.b);
}

TEST(MetallicRoughness, GoldShowsItsColourFromTheSurroundings) {
    const Surroundings studio = Surroundings::studio();
    MetallicRoughness gold;
    gold.base_colour = {1.0F, 0.766F, 0.336F}, gold.roughness = 0.3F;
    const MetallicRoughnessLighting lighting(gold, {}, &studio, {}, {}, {0, 0, -1});
    const LinearRgb seen = lighting.shade(facing({0, 0.6F, -0.8F}));
    EXPECT_GT(seen.r, 0.2F);
    EXPECT_GT(seen.r, seen.g);
    EXPECT_GT(seen.g, seen.b);
}

TEST(MetallicRoughness, DirectionalLightFollowsLambertForARoughDielectric) {
    MetallicRoughness matte;
    matte.metallic = 0.0F;
    const std::vector<raster::DirectionalLight> sun{{kNormal, 1.0F}};
    const MetallicRoughnessLighting lighting(matte, {}, nullptr, sun, {}, kNormal);
    const float head_on = lighting.shade(facing(kNormal)).r;
    EXPECT_GT(head_on, 0.9F);  // pi times (1 - F) / pi plus a faint rough highlight
    EXPECT_LT(head_on, 1.1F);
}

TEST(MetallicRoughness, EmissiveGlowsOnABlackSurface) {
    MetallicRoughness glow;
    glow.base_colour = {0, 0, 0}, glow.metallic = 0.0F, glow.emissive = {0, 1, 0};
    const MetallicRoughnessLighting lighting(glow, {}, nullptr, {}, {}, kNormal);
    EXPECT_EQ(lighting.shade(facing(kNormal)), (LinearRgb{0.0F, 1.0F, 0.0F}));
    glow.emissive_map = one_texel(255, 0, 0, raster::TexelEncoding::srgb);  // the map times its factor
    EXPECT_EQ(MetallicRoughnessLighting(glow, {}, nullptr, {}, {}, kNormal).shade(facing(kNormal)), (LinearRgb{}));
}

TEST(MetallicRoughness, FactorsOutsideTheirRangeAreClampedAndNaNTakesTheDefault) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    MetallicRoughness bad;
    bad.base_colour = {2.0F, -1.0F, nan}, bad.metallic = nan, bad.roughness = -3.0F, bad.emissive = {nan, -1, 5};
    bad.normal_scale = std::numeric_limits<float>::infinity();
    const MetallicRoughness usable = bad.usable();
    EXPECT_EQ(usable.base_colour, (LinearRgb{1.0F, 0.0F, 1.0F}));
    EXPECT_EQ(usable.metallic, 1.0F);
    EXPECT_EQ(usable.roughness, 0.0F);
    EXPECT_EQ(usable.emissive, (LinearRgb{0.0F, 0.0F, 5.0F}));
    EXPECT_EQ(usable.normal_scale, 1.0F);
}

TEST(MetallicRoughness, MapsMultiplyTheirFactorsReadAsLinearData) {
    MetallicRoughness m;
    m.metallic_roughness_map = one_texel(0, 128, 255, raster::TexelEncoding::linear);  // B metal, G rough
    m.occlusion_map = one_texel(51, 0, 0, raster::TexelEncoding::linear);
    m.occlusion_strength = 0.5F;
    const raster::MaterialSample s = MetallicRoughnessLighting(m, {}, nullptr, {}, {}, kNormal).sample(facing(kNormal));
    EXPECT_EQ(s.metallic, 1.0F);
    EXPECT_NEAR(s.roughness, 128.0F / 255.0F, 1e-6F);
    EXPECT_NEAR(s.occlusion, 1.0F + 0.5F * (0.2F - 1.0F), 1e-6F);
}

// A texel leaning toward +u turns the normal toward the direction in which u grows on screen.
TEST(MetallicRoughness, NormalMapLeansTheNormalAlongItsTangentFrame) {
    MetallicRoughness m;
    m.normal_map = one_texel(218, 128, 218, raster::TexelEncoding::linear);  // about (0.71, 0, 0.71)
    MaterialPoint p = facing(kNormal);
    p.position_per_x = {1, 0, 0}, p.position_per_y = {0, 1, 0};
    p.footprint = {{0.1F, 0.0F}, {0.0F, 0.1F}};  // u grows along +x, v along +y
    const glm::vec3 n = MetallicRoughnessLighting(m, {}, nullptr, {}, {}, kNormal).sample(p).normal;
    EXPECT_NEAR(n.x, 0.71F, 0.02F);
    EXPECT_NEAR(n.y, 0.0F, 0.02F);
    p.footprint = {{-0.1F, 0.0F}, {0.0F, 0.1F}};  // mirrored mapping: the lean follows u
    EXPECT_NEAR(MetallicRoughnessLighting(m, {}, nullptr, {}, {}, kNormal).sample(p).normal.x, -0.71F, 0.02F);
}

// A vertex tangent decides the frame where there is one: turned a quarter, the lean turns with
// it, whatever the screen derivatives say; w turns the bitangent, and a tangent along the normal
// leaves the screen's frame in charge.
TEST(MetallicRoughness, NormalMapFollowsTheVertexTangentTurnedAQuarter) {
    MetallicRoughness m;
    m.normal_map = one_texel(218, 128, 218, raster::TexelEncoding::linear);  // about (0.71, 0, 0.71): toward +u
    MaterialPoint p = facing(kNormal);
    p.position_per_x = {1, 0, 0}, p.position_per_y = {0, 1, 0};
    p.footprint = {{0.1F, 0.0F}, {0.0F, 0.1F}};  // the screen says u grows along +x
    const MetallicRoughnessLighting lighting(m, {}, nullptr, {}, {}, kNormal);
    p.tangent = {2, 0, 0.5F, 1};  // any length, a little off the surface: made perpendicular at the pixel
    EXPECT_NEAR(lighting.sample(p).normal.x, 0.71F, 0.02F);
    p.tangent = {0, 1, 0, 1};  // turned a quarter
    glm::vec3 n = lighting.sample(p).normal;
    EXPECT_NEAR(n.x, 0.0F, 0.02F);
    EXPECT_NEAR(n.y, 0.71F, 0.02F);
    p.tangent = {0, 0, 3, 1};  // along the normal: no direction in the surface
    EXPECT_NEAR(lighting.sample(p).normal.x, 0.71F, 0.02F);
    m.normal_map = one_texel(128, 218, 218, raster::TexelEncoding::linear);  // toward +v: the bitangent
    const MetallicRoughnessLighting toward_v(m, {}, nullptr, {}, {}, kNormal);
    p.tangent = {1, 0, 0, 1};  // w (n x t) = +y
    EXPECT_NEAR(toward_v.sample(p).normal.y, 0.71F, 0.02F);
    p.tangent.w = -1.0F;
    n = toward_v.sample(p).normal;
    EXPECT_NEAR(n.y, -0.71F, 0.02F);
    EXPECT_NEAR(n.x, 0.0F, 0.02F);
}

TEST(MetallicRoughness, NormalMapTurnedByItsTextureTransformTurnsTheVertexFrameWithIt) {
    MetallicRoughness m;
    m.normal_map = one_texel(218, 128, 218, raster::TexelEncoding::linear);  // toward +u'
    MaterialPoint p = facing(kNormal);
    p.tangent = {1, 0, 0, 1};                                        // u along +x, v along +y
    m.normal_transform.rotation = std::numbers::pi_v<float> / 2.0F;  // u' grows where v falls
    const glm::vec3 turned = MetallicRoughnessLighting(m, {}, nullptr, {}, {}, kNormal).sample(p).normal;
    EXPECT_NEAR(turned.x, 0.0F, 0.02F);
    EXPECT_NEAR(turned.y, -0.71F, 0.02F);
    m.normal_transform = {};
    m.normal_transform.scale = {-1.0F, 1.0F};  // u mirrored: u' grows along -x
    const glm::vec3 mirrored = MetallicRoughnessLighting(m, {}, nullptr, {}, {}, kNormal).sample(p).normal;
    EXPECT_NEAR(mirrored.x, -0.71F, 0.02F);
    EXPECT_NEAR(mirrored.y, 0.0F, 0.02F);
}

TEST(MetallicRoughness, ZeroVectorNormalTexelLeavesTheSurfaceNormal) {
    MetallicRoughness m;
    m.normal_map = one_texel(128, 128, 128, raster::TexelEncoding::linear);
    MaterialPoint p = facing(kNormal);
    p.position_per_x = {1, 0, 0}, p.position_per_y = {0, 1, 0};
    p.footprint = {{0.1F, 0.0F}, {0.0F, 0.1F}};
    EXPECT_EQ(MetallicRoughnessLighting(m, {}, nullptr, {}, {}, kNormal).sample(p).normal, kNormal);
}

TEST(Texture, LinearEncodingReadsBytesAsTheyAre) {
    const raster::Texture data(raster::Framebuffer(1, 1, {51, 102, 255}), raster::TexelEncoding::linear);
    const LinearRgb read = data.sample({0.5F, 0.5F}, {}, {});
    EXPECT_NEAR(read.r, 0.2F, 1e-6F);
    EXPECT_NEAR(read.g, 0.4F, 1e-6F);
    EXPECT_EQ(read.b, 1.0F);
}
