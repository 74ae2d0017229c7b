// Shading in lanes: every lane of pixels() gives exactly what pixel() gives for that pixel.
#include <raster/shade/textured_shaders.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <type_traits>
#include <vector>
#include <gtest/gtest.h>

using namespace raster;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

// Points a renderer meets and the ones the lighting treats apart: zero and NaN normals, points on
// a light, offsets too large or too small to square in float, normals of any length.
std::vector<SurfacePoint> awkward_points(std::span<const PointLight> lights) {
    std::mt19937 random(17);
    std::uniform_real_distribution<float> near(-3.0F, 3.0F);
    std::vector<SurfacePoint> points;
    for (int i = 0; i < 200; ++i)
        points.push_back({{near(random), near(random), near(random)}, {near(random), near(random), near(random)}});
    points.push_back({{0, 0, 0}, {0, 0, 0}});
    points.push_back({{0, 0, 0}, {std::numeric_limits<float>::quiet_NaN(), 0, 1}});
    points.push_back({lights[0].position, {0, 1, 0}});
    points.push_back({{3e20F, 0, 0}, {-1, 0, 0}});
    points.push_back({lights[1].position + glm::vec3(1e-25F, 0, 0), {0, 1, 0}});
    points.push_back({{1, 1, 1}, {kInf, 0, 0}});
    points.push_back({{1, 1, 1}, {1e-30F, 2e-30F, 0}});
    return points;
}

// The scalar and lane results of `shade` for every point, lanes filled kLanes at a time and
// the last batch short.
template <typename Scalar, typename Lanes>
void expect_lanes_match(std::span<const SurfacePoint> points, Scalar scalar, Lanes lanes) {
    for (std::size_t first = 0; first < points.size(); first += kLanes) {
        const auto batch = points.subspan(first, std::min<std::size_t>(kLanes, points.size() - first));
        std::array<Rgb, kLanes> out{};
        lanes(batch, std::span(out).first(batch.size()));
        for (std::size_t i = 0; i < batch.size(); ++i) {
            const Rgb expected = scalar(batch[i]);
            EXPECT_EQ(out[i], expected) << "point " << first + i << " at (" << batch[i].position.x << ", "
                                        << batch[i].position.y << ", " << batch[i].position.z << ") normal ("
                                        << batch[i].normal.x << ", " << batch[i].normal.y << ", " << batch[i].normal.z
                                        << ")";
        }
    }
}

struct Lights {
    std::vector<DirectionalLight> suns{{{1, 1, -1}, 0.7F}, {{-1, 0.2F, 0}, 0.3F}};
    std::vector<PointLight> lamps{{{0.5F, 1.0F, -0.5F}, 1.2F, {0.5F, 0.0F, 1.0F}},
                                  {{-1.0F, -0.5F, 0.0F}, 0.8F, {0.0F, 0.3F, 0.0F}}};
};

}  // namespace

TEST(Lanes, EveryLaneOfPhongEqualsItsPixelStageInBothViewsAndAnyShininess) {
    const Lights s;
    const std::vector<SurfacePoint> points = awkward_points(s.lamps);
    for (const std::optional<float> shininess :
         {std::optional<float>{}, std::optional<float>{30.0F}, std::optional<float>{7.5F}}) {
        const LinearMaterial material = LinearMaterial::from_srgb({7, 37, 52}, {21, 98, 137}, {68, 68, 68}, shininess);
        const LinearLighting orthographic(material, s.suns, s.lamps, {0, 0, -1});
        const LinearLighting perspective(material, s.suns, s.lamps, {0, 0, -1}, glm::vec3(0.2F, 0.3F, -4.0F),
                                         DepthDarkening{3.0F, 6.0F, 0.2F});
        for (const LinearLighting* lighting : {&orthographic, &perspective}) {
            const LinearPhongShader shader{lighting};
            expect_lanes_match(
                points, [&](const SurfacePoint& p) { return shader.pixel(p); },
                [&](std::span<const SurfacePoint> batch, std::span<Rgb> out) { shader.pixels(batch, out); });
        }
    }
}

TEST(Lanes, EveryLaneOfTexturedPhongEqualsItsPixelStage) {
    const Lights s;
    Framebuffer image(8, 8);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            image.set_pixel(x, y, {static_cast<std::uint8_t>(30 * x), static_cast<std::uint8_t>(30 * y), 200});
    }
    const Texture texture(image);
    const LinearMaterial material = LinearMaterial::from_srgb({0, 0, 0}, {255, 255, 255}, {40, 40, 40}, 12.0F);
    const LinearLighting lighting(material, s.suns, s.lamps, {0, 0, -1}, glm::vec3(0.0F, 0.0F, -4.0F));
    const TexturedPhongShader shader{&lighting, {material.diffuse, &texture, {}}};
    using Varying = TexturedPhongShader::Varying;
    const std::vector<SurfacePoint> points = awkward_points(s.lamps);
    // Texture coordinates and footprints of every size, from magnified to the smallest level.
    const auto varying = [](const SurfacePoint& p) {
        return Varying{p.position, p.normal, {p.position.x * 0.37F, p.position.y * 0.21F}, {}};
    };
    const auto step = [](const SurfacePoint& p) { return Varying{{}, {}, {p.position.z * 0.05F, 0.01F}, {}}; };
    expect_lanes_match(
        points, [&](const SurfacePoint& p) { return shader.pixel(varying(p), step(p), step(p)); },
        [&](std::span<const SurfacePoint> batch, std::span<Rgb> out) {
            std::vector<Varying> v, per_pixel;
            for (const SurfacePoint& p : batch) v.push_back(varying(p)), per_pixel.push_back(step(p));
            shader.pixels(v, per_pixel, per_pixel, out);
        });
}

TEST(Lanes, EveryLaneOfATextureReadEqualsSampleForEveryFilterAndWrap) {
    Framebuffer image(16, 8);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x)
            image.set_pixel(x, y,
                            {static_cast<std::uint8_t>(16 * x), static_cast<std::uint8_t>(31 * y),
                             static_cast<std::uint8_t>(7 * x * y)});
    }
    const Texture texture(image);
    std::mt19937 random(5);
    std::uniform_real_distribution<float> coordinate(-2.5F, 2.5F), exponent(-12.0F, 4.0F);
    const std::array<float, 6> odd{kInf, -kInf, std::numeric_limits<float>::quiet_NaN(), 1.0F, 0.0F, -1e-9F};
    for (const TextureFilter filter : {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear}) {
        for (const TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp}) {
            for (int batch = 0; batch < 60; ++batch) {
                LaneUvs at;
                for (std::size_t i = 0; i < kLanes; ++i) {
                    // Footprints from far below a texel to far above the whole image, some odd values.
                    const float step = std::exp2(exponent(random));
                    at.u[i] = batch % 10 == 0 ? odd[i % odd.size()] : coordinate(random);
                    at.v[i] = coordinate(random);
                    at.u_per_x[i] = step, at.v_per_x[i] = step * coordinate(random);
                    at.u_per_y[i] = batch % 7 == 0 ? odd[(i + 2) % odd.size()] : step * coordinate(random),
                    at.v_per_y[i] = step;
                }
                const int count = 1 + batch % kLanes;
                LaneRgb out;
                texture.sample_lanes(at, {filter, wrap}, out, count);
                for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
                    const LinearRgb expected = texture.sample(
                        {at.u[i], at.v[i]}, {{at.u_per_x[i], at.v_per_x[i]}, {at.u_per_y[i], at.v_per_y[i]}},
                        {filter, wrap});
                    EXPECT_EQ((LinearRgb{out.r[i], out.g[i], out.b[i]}), expected)
                        << "batch " << batch << " lane " << i;
                }
            }
        }
    }
}

TEST(Lanes, EveryLaneOfTheOtherTexturedShadersEqualsItsPixelStage) {
    Framebuffer image(8, 8);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            image.set_pixel(x, y, {static_cast<std::uint8_t>(32 * x), 90, static_cast<std::uint8_t>(32 * y)});
    }
    const Texture texture(image);
    const LinearMaterial material = LinearMaterial::from_srgb({10, 20, 30}, {200, 180, 160}, {40, 40, 40}, 12.0F);
    const LinearLighting lighting(material, {}, {}, {0, 0, -1});
    const DiffuseSource source{material.diffuse, &texture, {}};
    std::mt19937 random(9);
    std::uniform_real_distribution<float> any(-2.0F, 2.0F);
    const auto check = [&](const auto& shader, auto make) {
        using Varying = typename std::remove_cvref_t<decltype(shader)>::Varying;
        for (int batch = 0; batch < 30; ++batch) {
            std::vector<Varying> v, per_x, per_y;
            const std::size_t count = 1 + static_cast<std::size_t>(batch) % kLanes;
            for (std::size_t i = 0; i < count; ++i)
                v.push_back(make()), per_x.push_back(make()), per_y.push_back(make());
            std::array<Rgb, kLanes> out{};
            shader.pixels(v, per_x, per_y, std::span(out).first(count));
            for (std::size_t i = 0; i < count; ++i)
                EXPECT_EQ(out[i], shader.pixel(v[i], per_x[i], per_y[i])) << "batch " << batch << " lane " << i;
        }
    };
    check(UnlitShader{source}, [&] { return UnlitShader::Varying{{any(random), any(random)}, {}}; });
    check(TintedUnlitShader{source}, [&] {
        return TintedUnlitShader::Varying{{any(random), any(random)}, Tint<true>({any(random), any(random), 0.5F})};
    });
    check(TexturedFlatShader{&lighting, source}, [&] {
        return TexturedFlatShader::Varying{any(random), {any(random), 0.1F, 0.2F}, {any(random), any(random)}, {}};
    });
}

TEST(Lanes, EveryLaneOfTheDiarysPhongEqualsItsPixelStage) {
    const std::vector<DirectionalLight> suns{{{1, 1, -1}, 0.7F}, {{-1, 0.2F, 0}, 0.3F}, {{0, 0, 0}, 1.0F}};
    const std::vector<SurfacePoint> points = awkward_points(Lights{}.lamps);
    for (const std::optional<float> shininess :
         {std::optional<float>{}, std::optional<float>{30.0F}, std::optional<float>{2.5F}}) {
        const IntensityLighting lighting({{52, 110, 210}, 0.2F, 0.8F, shininess}, suns, {0, 0, -1});
        const PhongShader shader{&lighting};
        expect_lanes_match(
            points, [&](const SurfacePoint& p) { return shader.pixel(p.normal); },
            [&](std::span<const SurfacePoint> batch, std::span<Rgb> out) {
                std::vector<glm::vec3> normals;
                for (const SurfacePoint& p : batch) normals.push_back(p.normal);
                shader.pixels(normals, out);
            });
    }
}

// The untextured per-vertex shaders: a scale of the base colour (Phase 1) or an sRGB encode
// (Phase 2), on values at the rounding and clamping edges.
TEST(Lanes, EveryLaneOfFlatAndGouraudEqualsItsPixelStageInBothPhases) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> values{0.0F,
                              -0.0F,
                              -1.0F,
                              nan,
                              kInf,
                              -kInf,
                              1.0F,
                              2.0F,
                              0.5F / 255.0F,
                              1.5F / 255.0F,
                              254.5F / 255.0F,
                              std::nextafter(0.5F / 37.0F, 0.0F),
                              0.5F / 37.0F,
                              0.0031308F,
                              1e-30F,
                              0.9999999F};
    std::mt19937 random(29);
    std::uniform_real_distribution<float> any(-0.2F, 1.2F);
    for (int i = 0; i < 300; ++i) values.push_back(any(random));
    const std::vector<DirectionalLight> sun{{{0, 0, -1}, 1.0F}};
    const IntensityLighting lighting({{37, 110, 255}, 0.2F, 0.8F, std::nullopt}, sun, {0, 0, -1});
    const GouraudShader gouraud{&lighting};
    const LinearLighting linear_lighting(
        LinearMaterial::from_srgb({7, 37, 52}, {21, 98, 137}, {68, 68, 68}, std::nullopt), {}, {}, {0, 0, -1});
    const LinearGouraudShader linear{&linear_lighting};
    for (std::size_t first = 0; first < values.size(); first += kLanes) {
        const std::size_t n = std::min<std::size_t>(kLanes, values.size() - first);
        const std::span<const float> batch(values.data() + first, n);
        std::vector<LinearRgb> colours;  // each channel a different value, so lanes mix
        for (std::size_t i = 0; i < n; ++i) colours.push_back({batch[i], batch[(i + 1) % n], batch[(i + 2) % n]});
        std::array<Rgb, kLanes> scaled{}, encoded{};
        gouraud.pixels(batch, std::span(scaled).first(n));
        linear.pixels(colours, std::span(encoded).first(n));
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_EQ(scaled[i], gouraud.pixel(batch[i])) << "intensity " << batch[i];
            EXPECT_EQ(encoded[i], linear.pixel(colours[i]))
                << "colour " << colours[i].r << ", " << colours[i].g << ", " << colours[i].b;
        }
    }
}
