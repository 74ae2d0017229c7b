// The one rasterizer driven directly with test shaders; stays whole so each fill rule reads beside the rest.
#include <raster/shade/shaders.hpp>
#include "rasterize/setup_ortho.hpp"

#include "support/picture.hpp"

#include <raster/geometry/shapes.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::SubpixelPoint;
using raster::detail::ShadedCorner;
using test_support::looks_like;

namespace {

SubpixelPoint at(int x, int y) { return {x * raster::kSubpixelOne, y * raster::kSubpixelOne}; }

// Writes the interpolated value as a grey level, so pixels read back as numbers.
struct GreyShader {
    using Varying = float;
    [[nodiscard]] raster::Rgb pixel(float value) const noexcept {
        const auto level = static_cast<std::uint8_t>(std::lround(value));
        return {level, level, level};
    }
};

// A flat colour per triangle, to tell surfaces apart in pictures.
struct PaintShader {
    using Varying = float;
    raster::Rgb colour;
    [[nodiscard]] raster::Rgb pixel(float) const noexcept { return colour; }
};

std::array<ShadedCorner<float>, 3> corners(SubpixelPoint a, SubpixelPoint b, SubpixelPoint c, float depth_a = 0,
                                           float depth_b = 0, float depth_c = 0) {
    return {{{a, depth_a, 0.0F}, {b, depth_b, 0.0F}, {c, depth_c, 0.0F}}};
}

// Blue below 100, red from there: which of two overlapping triangles a pixel shows.
struct TwoTone {
    using Varying = float;
    [[nodiscard]] raster::Rgb pixel(float value) const noexcept {
        return value < 100 ? raster::Rgb{0, 0, 255} : raster::Rgb{255, 0, 0};
    }
};

// A picture and a depth buffer, the depth used only when `depth_test`, for triangles drawn
// through one batch.
struct BatchTarget {
    Framebuffer image{10, 5};
    raster::DepthBuffer depth;
    explicit BatchTarget(bool depth_test) { depth.prepare(10, 5), tested = depth_test ? &depth : nullptr; }
    raster::DepthBuffer* tested = nullptr;
};

}  // namespace

// Interpolates the pixel's own coordinates and a linear function of them: at every covered
// centre the shader sees (i, j, 10 + 10 i + 20 j) to within 1e-3, and paints what it saw.
TEST(ShadedTriangle, InterpolatesLinearlyAtEveryCoveredCentre) {
    struct Checker {
        using Varying = glm::vec3;
        [[nodiscard]] raster::Rgb pixel(const glm::vec3& v) const noexcept {
            const float i = std::round(v.x), j = std::round(v.y);
            const bool exact = std::abs(v.x - i) < 1e-3F && std::abs(v.y - j) < 1e-3F &&
                               std::abs(v.z - (10.0F + 10.0F * v.x + 20.0F * v.y)) < 1e-3F;
            return {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j),
                    exact ? std::uint8_t{255} : std::uint8_t{1}};
        }
    };
    const auto corner = [](double x, double y) {
        const raster::SubpixelPoint p{static_cast<std::int32_t>(x * raster::kSubpixelOne),
                                      static_cast<std::int32_t>(y * raster::kSubpixelOne)};
        return ShadedCorner<glm::vec3>{p, 0.0F, glm::vec3(x, y, 10.0 + 10.0 * x + 20.0 * y)};
    };
    Framebuffer image(16, 12);
    // Corners off the pixel centres (on the 1/256 grid, so the corner values are exact), clockwise on screen.
    raster::detail::shade_triangle(image, nullptr, {corner(0.25, 0.5), corner(14.75, 2.25), corner(3.125, 11.375)},
                                   Checker{});
    int covered = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const raster::Rgb c = image.pixel(i, j);
            if (c == raster::Rgb{}) continue;
            ++covered;
            EXPECT_EQ(c, (raster::Rgb{static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(j), 255}))
                << i << ", " << j;
        }
    }
    EXPECT_GT(covered, 60);
}

TEST(ShadedTriangle, EqualCornerValuesStayExactAcrossLongSpans) {
    Framebuffer image(300, 40);
    const float value = 0.1F + 127.0F;  // not exactly representable steps would drift
    std::array<ShadedCorner<float>, 3> triangle{
        {{at(-5, -3), 0, value}, {at(400, 7), 0, value}, {at(-20, 60), 0, value}}};
    struct Exact {
        using Varying = float;
        float expected;
        [[nodiscard]] raster::Rgb pixel(float v) const noexcept {
            return v == expected ? raster::Rgb{255, 255, 255} : raster::Rgb{255, 0, 0};
        }
    };
    raster::detail::shade_triangle(image, nullptr, triangle, Exact{value});
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            EXPECT_NE(image.pixel(i, j), (raster::Rgb{255, 0, 0})) << i << ", " << j;
    }
}

TEST(ShadedTriangle, DepthKeepsTheNearerSurfaceWhicheverIsDrawnFirst) {
    const raster::Rgb near{0, 0, 255}, far{255, 0, 0};
    for (const bool near_first : {true, false}) {
        Framebuffer image(10, 5);
        raster::DepthBuffer depth;
        depth.prepare(10, 5);
        const auto draw_near = [&] {
            raster::detail::shade_triangle(image, &depth, corners(at(0, 0), at(6, 0), at(0, 4), 1, 1, 1),
                                           PaintShader{near});
        };
        const auto draw_far = [&] {
            raster::detail::shade_triangle(image, &depth, corners(at(3, 0), at(9, 0), at(9, 4), 2, 2, 2),
                                           PaintShader{far});
        };
        if (near_first) {
            draw_near(), draw_far();
        } else {
            draw_far(), draw_near();
        }
        EXPECT_TRUE(looks_like(image, {"NNNNNNFFF.", "NNNNNFFFF.", "NNN...FFF.", "NN......F.", ".........."},
                               {{'N', near}, {'F', far}}))
            << (near_first ? "near first" : "far first");
    }
}

TEST(ShadedTriangle, InterpenetratingTrianglesCrossWhereTheirDepthsAreEqual) {
    const raster::Rgb tilted{0, 0, 255}, level{255, 0, 0};
    Framebuffer image(10, 5);
    raster::DepthBuffer depth;
    depth.prepare(10, 5);
    // Depth 1 everywhere, against one going from 0 on the left to 2 on the right: the tilted
    // one is in front up to x = 5, where the tie goes to it as the later.
    raster::detail::shade_triangle(image, &depth, corners(at(0, -1), at(19, -1), at(0, 10), 1, 1, 1),
                                   PaintShader{level});
    raster::detail::shade_triangle(image, &depth, corners(at(0, -1), at(10, -1), at(10, 10), 0, 2, 2),
                                   PaintShader{tilted});
    EXPECT_TRUE(looks_like(image, {"LTTTTTLLLL", "LLTTTTLLLL", "LLLTTTLLLL", "LLLLTTLLLL", "LLLLLTLLLL"},
                           {{'T', tilted}, {'L', level}}));
}

TEST(ShadedTriangle, OnEqualDepthTheLaterFacetWins) {
    const raster::Rgb first{0, 0, 255}, second{255, 0, 0};
    Framebuffer image(4, 3);
    raster::DepthBuffer depth;
    depth.prepare(4, 3);
    raster::detail::shade_triangle(image, &depth, corners(at(0, 0), at(4, 0), at(0, 3), 1, 1, 1), PaintShader{first});
    raster::detail::shade_triangle(image, &depth, corners(at(0, 0), at(4, 0), at(0, 3), 1, 1, 1), PaintShader{second});
    EXPECT_TRUE(looks_like(image, {"SSSS", "SSS.", "SS.."}, {{'F', first}, {'S', second}}));
}

// A batch left open across triangles (as a strip keeps it) still writes them in drawing order:
// the later triangle's pixels land over the earlier one's, and a farther one's not at all. The
// third has unequal corners and goes through the batch; the flat case is the next test.
TEST(ShadedTriangle, ABatchOpenAcrossTrianglesWritesInDrawingOrder) {
    const auto varied = [](std::array<ShadedCorner<float>, 3> c, float value) {  // unequal corners: no flat shortcut
        for (int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)].varying = value + static_cast<float>(k);
        return c;
    };
    for (const bool depth_test : {false, true}) {
        BatchTarget target(depth_test);
        Framebuffer& image = target.image;
        raster::DepthBuffer* const tested = target.tested;
        const TwoTone shader;
        raster::detail::LaneBatch<TwoTone> lanes(shader);
        raster::detail::shade_triangle(image, tested, varied(corners(at(0, 0), at(6, 0), at(0, 4), 1, 1, 1), 1), shader,
                                       {}, std::nullopt, &lanes);
        raster::detail::shade_triangle(image, tested, varied(corners(at(3, 0), at(9, 0), at(9, 4), 2, 2, 2), 101),
                                       shader, {}, std::nullopt, &lanes);
        raster::detail::shade_triangle(image, tested, varied(corners(at(5, 0), at(9, 0), at(5, 4), 3, 3, 3), 1), shader,
                                       {}, std::nullopt, &lanes);
        lanes.flush();
        // Without depth the third (blue, farthest) paints over the red; with it, it shows only
        // where nothing was drawn before it (column 5 of rows 2 and 3).
        const std::vector<std::string> expected =
            depth_test ? std::vector<std::string>{"BBBBBBRRR.", "BBBBBRRRR.", "BBB..BRRR.", "BB...B..R.", ".........."}
                       : std::vector<std::string>{"BBBRRBBBB.", "BBBBBBBBR.", "BBB..BBRR.", "BB...B..R.", ".........."};
        EXPECT_TRUE(looks_like(image, expected, {{'B', {0, 0, 255}}, {'R', {255, 0, 0}}}))
            << (depth_test ? "depth test" : "painter's order");
    }
}

// A flat triangle (equal corners) writes its one colour at once, not through the batch: pixels
// an earlier triangle left queued must land first, or they would cover it.
TEST(ShadedTriangle, AFlatTriangleAfterAnOpenBatchStillCoversTheEarlierOne) {
    for (const bool depth_test : {false, true}) {
        BatchTarget target(depth_test);
        Framebuffer& image = target.image;
        raster::DepthBuffer* const tested = target.tested;
        const TwoTone shader;
        raster::detail::LaneBatch<TwoTone> lanes(shader);
        auto red = corners(at(0, 0), at(8, 0), at(0, 4), 2, 2, 2);  // 20 pixels: four still queued at its end
        for (int k = 0; k < 3; ++k) red[static_cast<std::size_t>(k)].varying = 101.0F + static_cast<float>(k);
        raster::detail::shade_triangle(image, tested, red, shader, {}, std::nullopt, &lanes);
        raster::detail::shade_triangle(image, tested, corners(at(0, 0), at(10, 0), at(0, 5), 1, 1, 1), shader, {},
                                       std::nullopt, &lanes);
        lanes.flush();
        EXPECT_TRUE(looks_like(image, {"BBBBBBBBBB", "BBBBBBBB..", "BBBBBB....", "BBBB......", "BB........"},
                               {{'B', {0, 0, 255}}, {'R', {255, 0, 0}}}))
            << (depth_test ? "depth test" : "painter's order");
    }
}

// A whole mesh through one open batch draws what a batch per triangle draws: Gouraud tori lit
// from one side, whose unlit facets (equal corners) are flat among shaded ones, seen from many
// eyes, drawn in strips of 16 rows as the renderer draws them.
TEST(ShadedTriangle, AMeshThroughOneBatchEqualsABatchPerTriangle) {
    int differing = 0, views = 0;
    for (const int detail : {1, 2}) {
        const raster::Mesh torus = raster::torus(12 * detail, 8 * detail);
        for (const glm::vec3 toward :
             {glm::vec3(1.0F, 0.3F, 0.2F), glm::vec3(-1.0F, -1.0F, 0.2F), glm::vec3(0.0F, 1.0F, 0.2F)}) {
            const std::vector<raster::DirectionalLight> sun{{toward, 1.0F}};
            const raster::IntensityLighting lighting({{200, 120, 40}, 0.2F, 0.8F, std::nullopt}, sun, {0, 0, -1});
            const raster::GouraudShader shader{&lighting};
            for (const float height : {0.5F, 1.0F, 2.0F, 4.0F}) {
                for (const float side : {0.0F, 1.5F, -2.0F}) {
                    const auto camera = raster::OrthoCamera::look_at(160, 120, {side, height, 3.0F});
                    Framebuffer shared(160, 120), separate(160, 120);
                    raster::DepthBuffer shared_depth, separate_depth;
                    shared_depth.prepare(160, 120), separate_depth.prepare(160, 120);
                    for (int y = 0; y < 120; y += 16) {
                        const raster::PixelRect rows{0, y, 160, std::min(16, 120 - y)};
                        raster::detail::draw_facets(shared, &shared_depth, camera, torus, shader, {}, rows);
                        raster::detail::facing_triangles(
                            separate, &separate_depth, camera, torus, shader, [&](const auto& c) {
                                if (raster::detail::misses_rows({c[0].at, c[1].at, c[2].at}, rows)) return;
                                raster::detail::shade_triangle(separate, &separate_depth, c, shader, {}, rows);
                            });
                    }
                    differing += shared == separate ? 0 : 1;
                    ++views;
                }
            }
        }
    }
    EXPECT_EQ(differing, 0) << "of " << views << " views depend on the batch";
}
