// Pictures leave as PNG or WebP, opaque or on a transparent background, and read back exactly.
#include <raster/geometry/shapes.hpp>
#include <raster/io/obj_file.hpp>
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/scene.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <fstream>

using raster::Framebuffer;

namespace {

Framebuffer gradient(int width, int height) {
    Framebuffer image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.set_pixel(x, y,
                            {static_cast<std::uint8_t>(40 * x), static_cast<std::uint8_t>(70 * y),
                             static_cast<std::uint8_t>(x * y + 5)});
        }
    }
    return image;
}

// A checkerboard of opaque and transparent pixels, one corner half-covered.
std::vector<std::uint8_t> holes(int width, int height) {
    std::vector<std::uint8_t> alpha(static_cast<std::size_t>(width * height));
    for (std::size_t i = 0; i < alpha.size(); ++i) alpha[i] = (i % 2 == 0) ? 255 : 0;
    alpha[0] = 128;
    return alpha;
}

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Where alpha is 0 a pixel's colour is not kept, so pictures are compared where it is not.
void expect_same_where_seen(const Framebuffer& got, const Framebuffer& want, const std::vector<std::uint8_t>& alpha) {
    ASSERT_EQ(got.width(), want.width());
    for (int y = 0; y < want.height(); ++y) {
        for (int x = 0; x < want.width(); ++x) {
            if (alpha[static_cast<std::size_t>(y * want.width() + x)] != 0) {
                EXPECT_EQ(got.pixel(x, y), want.pixel(x, y)) << x << "," << y;
            }
        }
    }
}

}  // namespace

TEST(PngFile, RgbAndRgbaRoundTripExactly) {
    const Framebuffer image = gradient(6, 4);
    const raster::DecodedPng opaque = raster::decode_png(raster::encode_png(image), 1000);
    EXPECT_EQ(opaque.image, image);
    EXPECT_EQ(opaque.alpha, std::vector<std::uint8_t>(24, 255));
    const std::vector<std::uint8_t> alpha = holes(6, 4);
    const raster::DecodedPng seen_through = raster::decode_png(raster::encode_png(image, alpha), 1000);
    EXPECT_EQ(seen_through.alpha, alpha);
    EXPECT_EQ(seen_through.image, image);  // PNG keeps colour under alpha 0 too
}

TEST(PngFile, WrongAlphaGarbageAndOversizedImagesAreRefused) {
    const Framebuffer image = gradient(6, 4);
    EXPECT_THROW((void)raster::encode_png(image, std::vector<std::uint8_t>(23, 255)), std::invalid_argument);
    const std::vector<std::uint8_t> garbage{'n', 'o', 't', ' ', 'p', 'n', 'g'};
    EXPECT_THROW((void)raster::decode_png(garbage, 1000), std::runtime_error);
    EXPECT_THROW((void)raster::decode_png(raster::encode_png(image), 23), std::runtime_error);
    std::vector<std::uint8_t> cut = raster::encode_png(image);
    cut.resize(cut.size() / 2);
    EXPECT_THROW((void)raster::decode_png(cut, 1000), std::runtime_error);
}

TEST(WebpAlpha, AStillKeepsItsAlphaLosslessly) {
    const test_support::ScratchDir dir;
    const Framebuffer image = gradient(6, 4);
    const std::vector<std::uint8_t> alpha = holes(6, 4);
    write_bytes(dir / "a.webp", raster::encode_webp_still(image, raster::Effort::balanced, alpha));
    const raster::DecodedWebp read = raster::read_webp(dir / "a.webp");
    ASSERT_EQ(read.frames.size(), 1U);
    EXPECT_EQ(read.frames[0].alpha, alpha);
    expect_same_where_seen(read.frames[0].image, image, alpha);
    // Without alpha every pixel reads back opaque.
    write_bytes(dir / "b.webp", raster::encode_webp_still(image));
    EXPECT_EQ(raster::read_webp(dir / "b.webp").frames.at(0).alpha, std::vector<std::uint8_t>(24, 255));
}

TEST(WebpAlpha, TransparentAnimationsTakeTheAnimPathAndKeepAlphaInEveryFrame) {
    const test_support::ScratchDir dir;
    const Framebuffer image = gradient(6, 4);
    std::vector<std::uint8_t> first = holes(6, 4), second(24, 0);
    second[5] = 255;  // a pixel that turns transparent must not keep the frame before showing
    raster::AnimationEncoder parallel(6, 4, 50, {raster::Effort::fast, raster::AnimationPath::parallel});
    EXPECT_THROW(parallel.add_frame(image, first), std::invalid_argument);
    raster::AnimationEncoder anim(6, 4, 50, {raster::Effort::fast, raster::AnimationPath::anim});
    anim.add_frame(image, first);
    anim.add_frame(image, second);
    write_bytes(dir / "a.webp", anim.finish());
    const raster::DecodedWebp read = raster::read_webp(dir / "a.webp");
    ASSERT_EQ(read.frames.size(), 2U);
    EXPECT_EQ(read.frames[0].alpha, first);
    EXPECT_EQ(read.frames[1].alpha, second);
    expect_same_where_seen(read.frames[1].image, image, second);
}

TEST(Coverage, DepthIsKeptForOneConvexMeshOnlyWhenAskedAndItsCoverageIsWhatWasDrawn) {
    raster::Scene scene{
        raster::OrthoCamera::look_at(24, 18, {2.0F, 1.5F, -3.0F}, {0.0F, 0.0F, 0.0F}, {0.0F, 1.0F, 0.0F}),
        {10, 20, 30},
        {},
        {},
        {}};
    scene.objects.push_back({std::make_shared<const raster::Mesh>(raster::cube_mesh()), glm::mat4(1.0F),
                             raster::IntensityMaterial::matte({200, 100, 50}, 1.0F)});
    Framebuffer image(24, 18);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth);
    EXPECT_FALSE(depth.allocated()) << "one convex mesh needs no depth";
    scene.keep_depth = true;
    Framebuffer kept(24, 18);
    raster::render(kept, scene, depth);
    ASSERT_TRUE(depth.allocated());
    EXPECT_EQ(kept, image) << "keeping depth changes no pixel";
    const std::vector<std::uint8_t> alpha = depth.coverage();
    ASSERT_EQ(alpha.size(), 24U * 18U);
    int drawn = 0;
    for (int y = 0; y < 18; ++y) {
        for (int x = 0; x < 24; ++x) {
            const bool background = kept.pixel(x, y) == scene.background;
            EXPECT_EQ(alpha[static_cast<std::size_t>(y * 24 + x)], background ? 0 : 255) << x << "," << y;
            drawn += background ? 0 : 1;
        }
    }
    EXPECT_GT(drawn, 40);
    EXPECT_LT(drawn, 24 * 18 - 40);
}
