// Anti-aliasing by samples: each pass at a standard sample position, resolved in linear light.
#include <raster/image/colour.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

// A white unlit rectangle on black in a 9 x 9 view whose corners sit on pixel centres: columns 0
// to 4, rows 0 to 8. At one sample the fill rule leaves its right column and bottom row out.
raster::Scene white_rectangle(bool transparent = false) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions = {{-1.0F, -1.0F, 0.0F}, {0.0F, -1.0F, 0.0F}, {0.0F, 1.0F, 0.0F}, {-1.0F, 1.0F, 0.0F}};
    mesh->normals.assign(4, {0.0F, 0.0F, -1.0F});
    const glm::vec3 behind(-0.5F, 0.0F, 1.0F);  // normals face the camera at z = -1
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    raster::Scene scene{raster::OrthoCamera(9, 9), {0, 0, 0}, {}, {}, {}};
    scene.objects.push_back({mesh, glm::mat4(1.0F), raster::LinearMaterial{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {}},
                             raster::ShadingMethod::unlit});
    scene.keep_depth = transparent;
    return scene;
}

// How much of each pixel is white, read back from linear light: '#' all, 'o' a half, '+' a
// quarter, '.' none, '?' anything else.
std::vector<std::string> shares(const Framebuffer& image) {
    std::vector<std::string> rows;
    for (int y = 0; y < image.height(); ++y) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) {
            const double share = raster::linear_from_srgb_channel(image.pixel(x, y).g / 255.0);
            const auto near = [&](double value) { return std::abs(share - value) < 0.01; };
            row += near(1.0) ? '#' : near(0.5) ? 'o' : near(0.25) ? '+' : near(0.0) ? '.' : '?';
        }
        rows.push_back(row);
    }
    return rows;
}

Framebuffer drawn(const raster::Scene& scene, raster::RenderOptions options) {
    Framebuffer image(9, 9);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, options);
    return image;
}

}  // namespace

TEST(Samples, PositionsAreTheStandardPatternsOnTheSixteenthPixelGrid) {
    for (const int count : raster::kSampleCounts) {
        const auto offsets = raster::sample_offsets(count);
        ASSERT_EQ(offsets.size(), static_cast<std::size_t>(count));
        std::set<std::pair<float, float>> distinct;
        for (const glm::vec2 offset : offsets) {
            EXPECT_EQ(offset.x * 16.0F, std::round(offset.x * 16.0F));
            EXPECT_EQ(offset.y * 16.0F, std::round(offset.y * 16.0F));
            EXPECT_GE(offset.x, -0.5F);
            EXPECT_LT(offset.x, 0.5F);
            EXPECT_GE(offset.y, -0.5F);
            EXPECT_LT(offset.y, 0.5F);
            distinct.insert({offset.x, offset.y});
        }
        EXPECT_EQ(distinct.size(), offsets.size());
    }
    EXPECT_EQ(raster::sample_offsets(4)[0], glm::vec2(-2.0F / 16, -6.0F / 16));
    for (const int wrong : {0, 3, 32, -4})
        EXPECT_THROW((void)raster::sample_offsets(wrong), std::invalid_argument) << wrong;
}

TEST(Samples, EdgePixelsTakeTheShareOfSamplesCoveredInLinearLight) {
    EXPECT_EQ(shares(drawn(white_rectangle(), {})), (std::vector<std::string>{
                                                        "####.....",
                                                        "####.....",
                                                        "####.....",
                                                        "####.....",
                                                        "####.....",
                                                        "####.....",
                                                        "####.....",
                                                        "####.....",
                                                        ".........",
                                                    }));
    // Four samples: each edge through pixel centres covers two of four, each corner one.
    const std::vector<std::string> four{
        "+ooo+....", "o###o....", "o###o....", "o###o....", "o###o....",
        "o###o....", "o###o....", "o###o....", "+ooo+....",
    };
    EXPECT_EQ(shares(drawn(white_rectangle(), {.samples = 4})), four);
    // Half covered is linear 0.5, sRGB 188, not the 128 of a mean of bytes.
    EXPECT_EQ(drawn(white_rectangle(), {.samples = 4}).pixel(4, 4).g, 188);
    // Sixteen samples put eight on each side of a vertical edge through the centre, one on it
    // (left out by the fill rule on the right edge, kept on the left).
    const Framebuffer sixteen = drawn(white_rectangle(), {.samples = 16});
    EXPECT_NEAR(raster::linear_from_srgb_channel(sixteen.pixel(4, 4).g / 255.0), 8.0 / 16.0, 0.01);
    EXPECT_NEAR(raster::linear_from_srgb_channel(sixteen.pixel(0, 4).g / 255.0), 8.0 / 16.0, 0.01);
}

TEST(Samples, EachPassLooksFromItsSamplePositionInBothCameras) {
    // A pixel centre of the moved camera sees what lies `offset` from it: the screen position of
    // a world point moves by minus the offset, x right and y down alike.
    const glm::dvec2 offset(6.0 / 16, -2.0 / 16);
    const glm::vec3 point(0.3F, -0.2F, 0.5F);
    const raster::OrthoCamera flat = raster::OrthoCamera::look_at(64, 48, {0.0F, 0.0F, -3.0F});
    const glm::dvec2 moved = flat.sampled_at(offset).screen_from_world(point) - flat.screen_from_world(point);
    EXPECT_NEAR(moved.x, -offset.x, 1e-9);
    EXPECT_NEAR(moved.y, -offset.y, 1e-9);
    const raster::PerspectiveCamera lens = raster::PerspectiveCamera::look_at(
        64, 48, {0.0F, 0.0F, -3.0F}, {0.0F, 0.0F, 0.0F}, {0.0F, 1.0F, 0.0F}, {50.0, 0.1, 10.0});
    const glm::dvec4 clip = lens.clip_from_world(point);
    const glm::dvec2 seen = lens.sampled_at(offset).screen_from_clip(clip) - lens.screen_from_clip(clip);
    EXPECT_NEAR(seen.x, -offset.x, 1e-9);
    EXPECT_NEAR(seen.y, -offset.y, 1e-9);
}

// The spheres and tori of the diary's scenes, big enough for several strips and facet batches.
TEST(Samples, TheSamePictureOnAnyNumberOfThreads) {
    const raster::Scene scene = raster::DiaryScene("two-spheres").still(320, 400);
    for (const int count : {2, 4, 16}) {
        Framebuffer one(320, 400), three(320, 400);
        raster::DepthBuffer depth;
        raster::render(one, scene, depth, {.threads = 1, .samples = count});
        raster::render(three, scene, depth, {.threads = 3, .samples = count});
        EXPECT_EQ(one, three) << count;
    }
}

// Multisampling tests coverage and depth at the same positions a supersampled pass does, so on
// one flat colour the two agree exactly, in either camera; shading differs only inside pixels.
TEST(Samples, MultisamplingCoversWhatSupersamplingCovers) {
    for (const int count : raster::kSampleCounts) {
        EXPECT_EQ(drawn(white_rectangle(), {.samples = count}),
                  drawn(white_rectangle(), {.samples = count, .shade_every_sample = true}))
            << count;
        const raster::PerspectiveScene lens = raster::in_perspective(white_rectangle(), 9, 9, 70.0);
        Framebuffer multi(9, 9), super(9, 9);
        raster::DepthBuffer depth;
        raster::render(multi, lens, depth, {.samples = count});
        raster::render(super, lens, depth, {.samples = count, .shade_every_sample = true});
        EXPECT_EQ(multi, super) << count;
    }
}

TEST(Samples, ATransparentFrameKeepsTheSurfaceColourAndTakesCoverageAsAlpha) {
    raster::Scene scene = white_rectangle(true);
    scene.background = {0, 0, 255};  // must not leak into the surface's edge pixels
    Framebuffer image(9, 9);
    raster::Renderer renderer({.threads = 1, .samples = 4});
    renderer.render(image, scene);
    const std::vector<std::uint8_t> alpha = renderer.coverage();
    ASSERT_EQ(alpha.size(), 81U);
    EXPECT_EQ(alpha[4 * 9 + 2], 255);  // inside
    EXPECT_EQ(alpha[4 * 9 + 4], 128);  // half, on the right edge
    EXPECT_EQ(alpha[0], 64);           // a quarter, at the top-left corner
    EXPECT_EQ(alpha[4 * 9 + 7], 0);
    EXPECT_EQ(image.pixel(4, 4), (raster::Rgb{255, 255, 255}));  // the surface alone
    EXPECT_EQ(image.pixel(0, 0), (raster::Rgb{255, 255, 255}));
    EXPECT_EQ(image.pixel(7, 4), (raster::Rgb{0, 0, 255}));  // the background where nothing is
}

TEST(Samples, CountsOtherThanTheStandardOnesAreRefused) {
    Framebuffer image(9, 9);
    raster::DepthBuffer depth;
    EXPECT_THROW(raster::render(image, white_rectangle(), depth, {.samples = 3}), std::invalid_argument);
    EXPECT_THROW(raster::Renderer({.samples = 0}), std::invalid_argument);
}
