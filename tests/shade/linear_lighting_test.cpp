// Phase 2 light: materials in linear light, directional and point lights, falloff.
#include <raster/shade/linear_lighting.hpp>

#include <cmath>
#include <limits>
#include <vector>
#include <gtest/gtest.h>

using raster::DirectionalLight;
using raster::Falloff;
using raster::LinearLighting;
using raster::LinearMaterial;
using raster::LinearRgb;
using raster::PointLight;

namespace {

constexpr glm::vec3 kUp{0.0F, 1.0F, 0.0F};
constexpr glm::vec3 kOrigin{0.0F, 0.0F, 0.0F};
constexpr glm::vec3 kToEye{0.0F, 0.0F, -1.0F};
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

// Diffuse white only, so the red channel reads the summed diffuse factor.
LinearMaterial white_diffuse() { return {{0, 0, 0}, {1, 1, 1}, {0, 0, 0}, std::nullopt}; }

float diffuse_at(glm::vec3 position, glm::vec3 normal, std::vector<DirectionalLight> directional,
                 std::vector<PointLight> points = {}) {
    return LinearLighting(white_diffuse(), directional, points, kToEye).shade(position, normal).r;
}

bool finite(LinearRgb c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

}  // namespace

// The cases the original pinned for both kinds of light: aligned, oblique, orthogonal, away.
TEST(LinearLighting, DirectionalAndPointLightsAgreeOnLambert) {
    const Falloff none{};
    const float oblique = 1.0F / std::sqrt(2.0F);
    struct Case {
        glm::vec3 toward;
        float expected;
    };
    for (const Case& c : {Case{kUp, 1.0F}, Case{{1, 1, 0}, oblique}, Case{{1, 0, 0}, 0.0F}, Case{{0, -1, 0}, 0.0F}}) {
        EXPECT_NEAR(diffuse_at(kOrigin, kUp, {{c.toward, 1.0F}}), c.expected, 1e-6F) << c.toward.x << c.toward.y;
        // A point light along the same direction, any distance away, with no falloff.
        EXPECT_NEAR(diffuse_at(kOrigin, kUp, {}, {{c.toward * 7.0F, 1.0F, none}}), c.expected, 1e-6F);
    }
    EXPECT_EQ(diffuse_at(kOrigin, kUp, {{kUp, 0.0F}}, {{kUp, 0.0F, none}}), 0.0F);
}

TEST(LinearLighting, PointLightsDependOnTheSurfacePosition) {
    const std::vector<PointLight> lamp{{{0, 1, 0}, 1.0F, Falloff{}}};
    EXPECT_NEAR(diffuse_at({0, 0, 0}, kUp, {}, lamp), 1.0F, 1e-6F);                    // straight below
    EXPECT_NEAR(diffuse_at({1, 0, 0}, kUp, {}, lamp), 1.0F / std::sqrt(2.0F), 1e-6F);  // off to the side
    // The highlight follows the half vector between the light and the eye at each point.
    const LinearMaterial shiny{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, 30.0F};
    const LinearLighting lighting(shiny, {}, lamp, kUp);
    EXPECT_NEAR(lighting.shade({0, 0, 0}, kUp).r, 1.0F, 1e-6F);
    EXPECT_LT(lighting.shade({1, 0, 0}, kUp).r, 0.2F);
}

TEST(LinearLighting, FalloffAtKnownDistances) {
    const Falloff diary{1.0F, 0.0F, 1.0F};  // 1 / (1 + d^2): the original's test values
    EXPECT_NEAR(diffuse_at(kOrigin, kUp, {}, {{{0, 1, 0}, 1.0F, diary}}), 0.5F, 1e-6F);
    EXPECT_NEAR(diffuse_at(kOrigin, kUp, {}, {{{0, 2, 0}, 1.0F, diary}}), 0.2F, 1e-6F);
    const Falloff scene{0.5F, 0.0F, 1.0F};  // the scenes': 1 / (0.5 + d^2)
    EXPECT_NEAR(diffuse_at(kOrigin, kUp, {}, {{{0, 2, 0}, 3.0F, scene}}), 3.0F / 4.5F, 1e-6F);
    const Falloff linear{0.0F, 2.0F, 0.0F};
    EXPECT_NEAR(diffuse_at(kOrigin, kUp, {}, {{{0, 4, 0}, 1.0F, linear}}), 1.0F / 8.0F, 1e-6F);
    // Falloff scales the highlight as well as the diffuse light.
    const LinearMaterial both{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 8.0F};
    const LinearRgb c =
        LinearLighting(both, {}, std::vector<PointLight>{{{0, 2, 0}, 1.0F, diary}}, kUp).shade(kOrigin, kUp);
    EXPECT_NEAR(c.r, 0.2F, 1e-6F);
    EXPECT_NEAR(c.g, 0.2F, 1e-6F);
}

TEST(LinearLighting, EmissiveOnlyMaterialsIgnoreLight) {
    const LinearMaterial gold = LinearMaterial::from_srgb({255, 215, 0}, {0, 0, 0}, {0, 0, 0}, std::nullopt);
    const std::vector<DirectionalLight> sun{{kUp, 5.0F}};
    const std::vector<PointLight> lamp{{{0, 1, 0}, 9.0F, Falloff{}}};
    for (const glm::vec3 normal : {kUp, -kUp, glm::vec3(0.0F)}) {
        EXPECT_EQ(LinearLighting(gold, sun, lamp, kToEye).shade(kOrigin, normal), gold.emissive);
        EXPECT_EQ(LinearLighting(gold, {}, {}, kToEye).shade(kOrigin, normal), gold.emissive);
    }
    EXPECT_EQ(raster::srgb_from_linear(gold.emissive), (raster::Rgb{255, 215, 0}));
}

TEST(LinearLighting, IntensityScalesDiffuseAndSpecularButNotEmissive) {
    const LinearMaterial m = LinearMaterial::from_srgb({7, 37, 52}, {21, 98, 137}, {68, 68, 68}, 30.0F);
    const glm::vec3 normal = glm::normalize(glm::vec3(1, 2, -1));
    for (const bool point : {false, true}) {
        const auto lit = [&](float intensity) {
            if (point)
                return LinearLighting(m, {}, std::vector<PointLight>{{{1, 2, -1}, intensity, Falloff{}}}, kToEye);
            return LinearLighting(m, std::vector<DirectionalLight>{{{1, 2, -1}, intensity}}, {}, kToEye);
        };
        const LinearRgb once = lit(1.0F).shade(kOrigin, normal) - m.emissive;
        const LinearRgb thrice = lit(3.0F).shade(kOrigin, normal) - m.emissive;
        EXPECT_NEAR(thrice.r, 3.0F * once.r, 1e-6F);
        EXPECT_NEAR(thrice.g, 3.0F * once.g, 1e-6F);
        EXPECT_NEAR(thrice.b, 3.0F * once.b, 1e-6F);
        EXPECT_GT(once.b, 0.0F);
        EXPECT_EQ(lit(0.0F).shade(kOrigin, normal), m.emissive);
    }
}

TEST(LinearLighting, SeveralLightsAddUp) {
    const std::vector<DirectionalLight> two{{kUp, 0.25F}, {{1, 1, 0}, 0.5F}};
    const float sum = diffuse_at(kOrigin, kUp, {two[0]}) + diffuse_at(kOrigin, kUp, {two[1]});
    EXPECT_NEAR(diffuse_at(kOrigin, kUp, two, {{{0, 3, 0}, 1.0F, Falloff{}}}), sum + 1.0F, 1e-6F);
}

// The original panicked when a light sat on the surface; here every odd input has a defined
// result and no NaN reaches a pixel.
TEST(LinearLighting, OddLightsGiveDefinedResultsNeverNaN) {
    const Falloff none{}, inverse_square{0.0F, 0.0F, 1.0F};
    // A light exactly at the surface point has no direction: it adds nothing there.
    EXPECT_EQ(diffuse_at(kOrigin, kUp, {}, {{kOrigin, 1.0F, none}}), 0.0F);
    EXPECT_EQ(diffuse_at(kOrigin, kUp, {}, {{kOrigin, 1.0F, inverse_square}}), 0.0F);
    // Just off it, an inverse-square light is held at kBrightest, not infinite.
    const float close = diffuse_at(kOrigin, kUp, {}, {{{0, 1e-25F, 0}, 1.0F, inverse_square}});
    EXPECT_TRUE(std::isfinite(close));
    EXPECT_EQ(close, LinearLighting::kBrightest);
    // A negative intensity takes light away; the write clamps the result at black.
    EXPECT_NEAR(diffuse_at(kOrigin, kUp, {{kUp, 1.0F}}, {{{0, 1, 0}, -0.25F, none}}), 0.75F, 1e-6F);
    EXPECT_EQ(raster::srgb_from_linear(
                  LinearLighting(white_diffuse(), {}, std::vector<PointLight>{{{0, 1, 0}, -1.0F, none}}, kToEye)
                      .shade(kOrigin, kUp)),
              (raster::Rgb{0, 0, 0}));
    // Unusable lights add nothing: non-finite positions and intensities, broken falloffs.
    for (const PointLight& broken :
         {PointLight{{kNaN, 1, 0}, 1.0F, none}, PointLight{{0, kInf, 0}, 1.0F, none}, PointLight{{0, 1, 0}, kNaN, none},
          PointLight{{0, 1, 0}, kInf, none}, PointLight{{0, 1, 0}, 1.0F, {0, 0, 0}},
          PointLight{{0, 1, 0}, 1.0F, {-1, 0, 1}}, PointLight{{0, 1, 0}, 1.0F, {1, kNaN, 0}}}) {
        EXPECT_EQ(diffuse_at(kOrigin, kUp, {}, {broken}), 0.0F);
    }
    // Huge distances: with falloff the light fades to nothing, without it the direction holds.
    EXPECT_EQ(diffuse_at(kOrigin, kUp, {}, {{{0, 3e38F, 0}, 1.0F, inverse_square}}), 0.0F);
    EXPECT_NEAR(diffuse_at({0, -3e38F, 0}, kUp, {}, {{{0, 3e38F, 0}, 1.0F, none}}), 1.0F, 1e-6F);
    EXPECT_NEAR(diffuse_at({0, -3e38F, 0}, kUp, {}, {{{0, 3e38F, 0}, 1.0F, {1.0F, 0.0F, 0.0F}}}), 1.0F, 1e-6F);
    EXPECT_EQ(diffuse_at({0, -3e38F, 0}, kUp, {}, {{{0, 3e38F, 0}, 1.0F, {1.0F, 1.0F, 0.0F}}}), 0.0F);
    // A zero normal is "no normal": emissive only, whatever shines.
    const LinearMaterial glowing{{0.1F, 0.2F, 0.3F}, {1, 1, 1}, {1, 1, 1}, 0.0F};
    EXPECT_EQ(
        LinearLighting(glowing, std::vector<DirectionalLight>{{kUp, 1.0F}}, {}, kToEye).shade(kOrigin, glm::vec3(0.0F)),
        glowing.emissive);
    // An infinite shininess, where a dot of unit vectors rounding above 1 would give infinity.
    const LinearMaterial mirror{{0, 0, 0}, {0, 0, 0}, {1, 1, 1}, kInf};
    for (int i = 0; i < 1000; ++i) {
        const auto t = static_cast<float>(i);
        const glm::vec3 n =
            glm::normalize(glm::vec3(std::sin(t * 0.37F), std::cos(t * 0.71F), std::sin(t * 1.3F) - 1.5F));
        const std::vector<PointLight> faded{{{0, 3e38F, 0}, 1.0F, inverse_square}};
        const LinearLighting lit(mirror, std::vector<DirectionalLight>{{n, 1.0F}, {-n, -1.0F}}, faded, n);
        ASSERT_TRUE(finite(lit.shade(kOrigin, n))) << i;
    }
    // Every combination above with a shininess, several lights at once: finite.
    const std::vector<PointLight> all{{kOrigin, 1e30F, inverse_square},
                                      {{0, 1e-30F, 0}, 3e38F, inverse_square},
                                      {{0, 3e38F, 0}, -3e38F, none},
                                      {{0, 1, 0}, 1.0F, inverse_square}};
    const LinearMaterial shiny{{0, 0, 0}, {1, 1, 1}, {1, 1, 1}, 0.5F};
    for (const glm::vec3 normal : {kUp, -kUp, glm::vec3(1, 0, 0)}) {
        EXPECT_TRUE(finite(
            LinearLighting(shiny, std::vector<DirectionalLight>{{kUp, 3e38F}}, all, kToEye).shade(kOrigin, normal)));
    }
}
