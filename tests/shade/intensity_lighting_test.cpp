#include <raster/shade/intensity_lighting.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using raster::DirectionalLight;
using raster::IntensityLighting;
using raster::IntensityMaterial;

namespace {

constexpr raster::Rgb kBlue{52, 110, 210};
constexpr glm::vec3 kToEye{0, 0, -1};

float intensity(const IntensityMaterial& material, glm::vec3 toward, glm::vec3 normal, glm::vec3 to_eye = kToEye) {
    const std::array lights{DirectionalLight{toward}};
    return IntensityLighting(material, lights, to_eye).intensity(normal);
}

}  // namespace

TEST(Lambert, FullyLitFacingTheLightDarkSideways) {
    const IntensityMaterial matte = IntensityMaterial::matte(kBlue, 0.25F);
    EXPECT_FLOAT_EQ(intensity(matte, {0, 0, -1}, {0, 0, -1}), 1.0F);
    EXPECT_FLOAT_EQ(intensity(matte, {1, 0, 0}, {0, 0, -1}), 0.25F) << "perpendicular: ambient only";
    EXPECT_FLOAT_EQ(intensity(matte, {0, 0, 1}, {0, 0, -1}), 0.25F) << "facing away: ambient only";
    EXPECT_FLOAT_EQ(intensity(matte, {0, 0, -5}, {0, 0, -1}), 1.0F) << "the light's length does not matter";
    EXPECT_NEAR(intensity(matte, {1, 0, -1}, {0, 0, -1}), 0.25F + 0.75F / std::sqrt(2.0F), 1e-6F);
}

TEST(Lambert, FullAmbientIsOneEverywhere) {
    for (const glm::vec3 normal : {glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)}) {
        EXPECT_FLOAT_EQ(intensity(IntensityMaterial::matte(kBlue, 1.0F), {1, 1, -1}, normal), 1.0F);
    }
}

TEST(BlinnPhong, SpecularFollowsTheHalfVector) {
    const auto specular = [](float shininess, glm::vec3 toward, glm::vec3 normal, glm::vec3 to_eye) {
        const IntensityMaterial pure{kBlue, 0.0F, 1.0F, shininess};
        return intensity(pure, toward, normal, to_eye) - std::max(0.0F, glm::dot(glm::normalize(toward), normal));
    };
    EXPECT_NEAR(specular(100, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}), 1.0F, 1e-6F) << "view, light and normal aligned";
    // Light along the normal, eye at the tangent: h is 45 degrees off n.
    EXPECT_NEAR(specular(1, {0, 0, -1}, {0, 0, -1}, {1, 0, 0}), 1.0F / std::sqrt(2.0F), 1e-6F);
    EXPECT_NEAR(specular(2, {0, 0, -1}, {0, 0, -1}, {1, 0, 0}), 0.5F, 1e-6F);
    EXPECT_NEAR(specular(128, {0, 0, -1}, {0, 0, -1}, {1, 0, 0}), 0.0F, 1e-6F);
    EXPECT_NEAR(specular(0, {0, 0, -1}, {0, 1, 0}, {1, 0, 0}), 1.0F, 1e-6F) << "shininess 0 is 1 everywhere";
    EXPECT_NEAR(specular(100, {0, 0, 1}, {0, 0, -1}, {0, 0, 1}), 0.0F, 1e-6F) << "half vector facing away";
}

TEST(BlinnPhong, MatteSurfacesDoNotDependOnTheViewer) {
    const IntensityMaterial matte = IntensityMaterial::matte(kBlue, 0.25F);
    EXPECT_FLOAT_EQ(intensity(matte, {1, 1, -1}, {0, 0, -1}, {0, 0, -1}),
                    intensity(matte, {1, 1, -1}, {0, 0, -1}, {1, 0, 0}));
}

TEST(IntensityLighting, UnusableLightsAddNothingAndNoNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const IntensityMaterial shiny = IntensityMaterial::shiny(kBlue, 0.15F, 100.0F);
    for (const glm::vec3 toward : {glm::vec3(0), glm::vec3(nan, 1, 0), glm::vec3(inf, 0, 0)}) {
        EXPECT_FLOAT_EQ(intensity(shiny, toward, {0, 0, -1}), 0.15F);
    }
    const std::array lights{DirectionalLight{{0, 0, -1}, nan}};
    EXPECT_FLOAT_EQ(IntensityLighting(shiny, lights, kToEye).intensity({0, 0, -1}), 0.15F);
    EXPECT_FLOAT_EQ(intensity(shiny, {0, 0, -1}, {0, 0, 0}), 0.15F) << "no normal: ambient only";
    // Not even pow(0, 0) = 1 sneaks a highlight onto a missing normal.
    EXPECT_FLOAT_EQ(intensity(IntensityMaterial::shiny(kBlue, 0.15F, 0.0F), {0, 0, -1}, {0, 0, 0}), 0.15F);
    // A negative shininess would make pow(0, s) infinite; it counts as 0.
    const IntensityMaterial negative = IntensityMaterial::shiny(kBlue, 0.0F, -3.0F);
    EXPECT_FLOAT_EQ(intensity(negative, {0, 0, -1}, {1, 0, 0}, {0, 0, -1}),
                    intensity(IntensityMaterial::shiny(kBlue, 0.0F, 0.0F), {0, 0, -1}, {1, 0, 0}, {0, 0, -1}));
    EXPECT_TRUE(std::isfinite(intensity(negative, {0, 0, 1}, {0, 0, -1}, {0, 0, 1})));
}

TEST(ScaledColour, RoundsPerChannelAndClampsNegativeHugeAndNaN) {
    EXPECT_EQ(raster::scaled_colour(kBlue, 1.0F), kBlue);
    EXPECT_EQ(raster::scaled_colour(kBlue, 0.5F), (raster::Rgb{26, 55, 105}));
    EXPECT_EQ(raster::scaled_colour({3, 5, 7}, 0.5F), (raster::Rgb{2, 3, 4})) << "halves round away from zero";
    EXPECT_EQ(raster::scaled_colour(kBlue, 2.0F), (raster::Rgb{104, 220, 255}));
    EXPECT_EQ(raster::scaled_colour(kBlue, -1.0F), (raster::Rgb{0, 0, 0}));
    EXPECT_EQ(raster::scaled_colour(kBlue, std::numeric_limits<float>::quiet_NaN()), (raster::Rgb{0, 0, 0}));
    EXPECT_EQ(raster::scaled_colour(kBlue, std::numeric_limits<float>::infinity()), (raster::Rgb{255, 255, 255}));
}
