// Textures: coordinates, filters, addressing, mip levels, files; stays whole as the one texture suite.
#include <raster/image/colour.hpp>
#include <raster/io/texture_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/shade/texture.hpp>

#include "support/encoded_images.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <string>

using raster::Framebuffer;
using raster::LinearRgb;
using raster::Rgb;
using raster::Sampler;
using raster::Texture;
using raster::TextureFilter;
using raster::TextureWrap;

namespace {

constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kWhite{255, 255, 255}, kBlack{0, 0, 0};

// Top row red, green; bottom row blue, white.
Texture two_by_two() {
    Framebuffer image(2, 2);
    image.set_pixel(0, 0, kRed);
    image.set_pixel(1, 0, kGreen);
    image.set_pixel(0, 1, kBlue);
    image.set_pixel(1, 1, kWhite);
    return Texture(image);
}

Rgb at(const Texture& texture, float u, float v, Sampler sampler, raster::UvFootprint footprint = {}) {
    return raster::srgb_from_linear(texture.sample({u, v}, footprint, sampler));
}

const Sampler kNearest{TextureFilter::nearest, TextureWrap::repeat};
const Sampler kBilinear{TextureFilter::bilinear, TextureWrap::repeat};

}  // namespace

TEST(Texture, VRunsUpSoTheImagesFirstRowIsAtTheTop) {
    const Texture texture = two_by_two();
    EXPECT_EQ(at(texture, 0.25F, 0.75F, kNearest), kRed);
    EXPECT_EQ(at(texture, 0.75F, 0.75F, kNearest), kGreen);
    EXPECT_EQ(at(texture, 0.25F, 0.25F, kNearest), kBlue);
    EXPECT_EQ(at(texture, 0.75F, 0.25F, kNearest), kWhite);
}

TEST(Texture, BilinearIsExactAtTexelCentresAndBlendsInLinearLightBetween) {
    const Texture texture = two_by_two();
    const Sampler clamped{TextureFilter::bilinear, TextureWrap::clamp};
    EXPECT_EQ(at(texture, 0.25F, 0.75F, clamped), kRed);
    EXPECT_EQ(at(texture, 0.75F, 0.25F, clamped), kWhite);
    // Half way from blue to white: half of white's linear light in red and green, full blue.
    const std::uint8_t half = raster::srgb_byte_from_linear(0.5F);
    EXPECT_EQ(at(texture, 0.5F, 0.25F, clamped), (Rgb{half, half, 255}));
    EXPECT_EQ(half, 188);  // not 128: the blend is of light, not of sRGB codes
}

TEST(Texture, RepeatTilesTheImageAndClampStretchesItsEdge) {
    const Texture texture = two_by_two();
    EXPECT_EQ(at(texture, 1.25F, 0.75F, kNearest), kRed);
    EXPECT_EQ(at(texture, -0.25F, 0.75F, kNearest), kGreen);
    const Sampler clamped{TextureFilter::nearest, TextureWrap::clamp};
    EXPECT_EQ(at(texture, 1.25F, 0.75F, clamped), kGreen);
    EXPECT_EQ(at(texture, -7.0F, -3.0F, clamped), kBlue);
    // Bilinear across the seam blends the last column with the first when repeating.
    EXPECT_EQ(at(texture, 1.0F, 0.75F, kBilinear), at(texture, 0.0F, 0.75F, kBilinear));
}

TEST(Texture, MipLevelsHalveDownToOneTexelAveragingInLinearLight) {
    const Texture texture(test_support::checkerboard(4, 1, kBlack, kWhite));
    ASSERT_EQ(texture.level_count(), 3U);
    EXPECT_EQ(texture.level(1).width(), 2);
    EXPECT_EQ(texture.level(2).width(), 1);
    const std::uint8_t grey = raster::srgb_byte_from_linear(0.5F);
    EXPECT_EQ(texture.level(1).pixel(1, 1), (Rgb{grey, grey, grey}));
    EXPECT_EQ(texture.level(2).pixel(0, 0), (Rgb{grey, grey, grey}));
    const Texture odd(Framebuffer(5, 3));
    EXPECT_EQ(odd.level_count(), 3U);  // 5x3, 2x1, 1x1
    EXPECT_EQ(odd.level(1).height(), 1);
}

TEST(Texture, TrilinearPicksTheLevelWhoseTexelsMatchThePixelStep) {
    const Texture texture(test_support::checkerboard(8, 1, kBlack, kWhite));
    const Sampler trilinear{TextureFilter::trilinear, TextureWrap::repeat};
    const float texel = 1.0F / 8.0F;
    // One texel per pixel: level 0, the texel itself.
    EXPECT_EQ(at(texture, 0.5F * texel, 1.0F - 0.5F * texel, trilinear, {{texel, 0.0F}, {0.0F, texel}}), kBlack);
    // Two texels per pixel: level 1, where the checkerboard has become grey.
    const std::uint8_t grey = raster::srgb_byte_from_linear(0.5F);
    EXPECT_EQ(at(texture, 0.5F * texel, 1.0F - 0.5F * texel, trilinear, {{2 * texel, 0.0F}, {0.0F, 2 * texel}}),
              (Rgb{grey, grey, grey}));
    // Bilinear ignores the footprint.
    EXPECT_EQ(at(texture, 0.5F * texel, 1.0F - 0.5F * texel, kBilinear, {{2 * texel, 0.0F}, {0.0F, 2 * texel}}),
              kBlack);
}

TEST(Texture, BetweenLevelsTrilinearBlendsByTheFractionOfTheLevel) {
    // Left half black, right half white: levels 0 and 1 keep the halves, level 2 is grey.
    Framebuffer halves(4, 4);
    for (int y = 0; y < 4; ++y) halves.fill_row(y, 2, 4, kWhite);
    const Texture texture(halves);
    ASSERT_EQ(texture.level_count(), 3U);
    const Sampler trilinear{TextureFilter::trilinear, TextureWrap::clamp};
    const float step = 3.0F / 4.0F;  // three level-0 texels a pixel: lambda = log2(3) = 1.585
    const LinearRgb c = texture.sample({0.25F, 0.5F}, {{step, 0.0F}, {0.0F, step}}, trilinear);
    const float blend = std::log2(3.0F) - 1.0F;
    const float grey =
        raster::linear_from_srgb(texture.level(2).pixel(0, 0)).r;  // 0.5, as the nearest sRGB byte holds it
    EXPECT_NEAR(c.r, grey * blend, 1e-5F);                         // level 1 black, level 2 grey
    EXPECT_NEAR(c.g, c.r, 1e-6F);
}

TEST(TextureFile, FormatsBeyondTheDocumentedOnesAreRefused) {
    for (const std::string& head :
         {std::string("GIF89a\x01\0\x01\0", 10), std::string("8BPS\0\x01"), std::string("P6\n1 1\n255\n\0\0\0", 14)}) {
        const std::vector<std::uint8_t> bytes(head.begin(), head.end());
        EXPECT_THROW((void)raster::decode_texture(bytes), std::runtime_error) << head;
    }
}

TEST(Texture, NonFiniteCoordinatesAndFootprintsStillGiveAColour) {
    const Texture texture(test_support::checkerboard(8, 2, kBlack, kWhite));
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const TextureFilter filter : {TextureFilter::nearest, TextureFilter::bilinear, TextureFilter::trilinear}) {
        for (const TextureWrap wrap : {TextureWrap::repeat, TextureWrap::clamp}) {
            for (const float u : {nan, inf, -inf, 1e30F, -1e30F, -0.0F}) {
                const LinearRgb c = texture.sample({u, u}, {{nan, inf}, {u, 1e30F}}, {filter, wrap});
                EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
            }
        }
    }
}

TEST(TextureFile, PngBmpTgaAndWebpReadToTheSameTexels) {
    const test_support::ScratchDir dir;
    const Framebuffer image = test_support::checkerboard(3, 2, Rgb{12, 200, 99}, Rgb{250, 7, 64});
    test_support::write_png(dir / "t.png", image);
    test_support::write_bmp(dir / "t.bmp", image);
    test_support::write_tga(dir / "t.tga", image);
    raster::write_webp_still(image, dir / "t.webp");
    for (const char* name : {"t.png", "t.bmp", "t.tga", "t.webp"}) {
        EXPECT_EQ(raster::read_texture(dir / name).level(0), image) << name;
    }
}

TEST(TextureFile, ImagesOverTheLimitAreRefusedFromTheirHeader) {
    const test_support::ScratchDir dir;
    test_support::write_png(dir / "wide.png", Framebuffer(64, 2));
    try {
        (void)raster::read_texture(dir / "wide.png", 100);
        FAIL() << "a 128-texel image passed a 100-texel limit";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("64x2, more than the 100 texels allowed"), std::string::npos)
            << error.what();
    }
    // A BMP header claiming 30000 x 30000 pixels in 54 bytes: refused without allocating them.
    Framebuffer tiny(1, 1);
    test_support::write_bmp(dir / "liar.bmp", tiny);
    std::fstream patch(dir / "liar.bmp", std::ios::in | std::ios::out | std::ios::binary);
    patch.seekp(18);
    const char huge[8] = {0x30, 0x75, 0, 0, 0x30, 0x75, 0, 0};
    patch.write(huge, 8);
    patch.close();
    EXPECT_THROW((void)raster::read_texture(dir / "liar.bmp"), std::runtime_error);
}

TEST(TextureFile, BadFilesGiveOneLineNamingTheFile) {
    const test_support::ScratchDir dir;
    test_support::write_text(dir / "notes.png", "not an image at all");
    test_support::write_png(dir / "whole.png", Framebuffer(16, 16));
    const std::string whole = test_support::read_text(dir / "whole.png");
    test_support::write_text(dir / "cut.png", whole.substr(0, whole.size() / 2));
    test_support::write_text(dir / "cut.webp", "RIFF\x10\0\0\0WEBPVP8L");
    for (const char* name : {"notes.png", "cut.png", "cut.webp", "missing.png", "."}) {
        try {
            (void)raster::read_texture(dir / name);
            ADD_FAILURE() << name << " was read";
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            EXPECT_EQ(message.rfind((dir / name).string() + ": ", 0), 0U) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

namespace {

// The message read_texture throws for `path`, or "" when it reads it.
std::string texture_error(const std::filesystem::path& path) {
    try {
        (void)raster::read_texture(path);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(TextureFile, AnImageOfAnyFormatCutShortIsRefusedAsTruncated) {
    const test_support::ScratchDir dir;
    test_support::Bytes pixels;
    for (int i = 0; i < 40 * 30 * 3; ++i) pixels.push_back(static_cast<std::uint8_t>(i * 37 % 251));
    std::vector<std::pair<std::string, test_support::Bytes>> files{
        {"t.png", test_support::encode_png(pixels, 40, 30, 3)},
        {"t.jpg", test_support::encode_jpeg(pixels, 40, 30, 3)},
        {"t.bmp", test_support::encode_bmp(pixels, 40, 30, 3)},
        {"t.tga", test_support::encode_tga(pixels, 40, 30, 3, false)},
        {"rle.tga", test_support::encode_tga(pixels, 40, 30, 3, true)}};
    raster::write_webp_still(Framebuffer(40, 30, pixels), dir / "t.webp");
    const std::string webp = test_support::read_text(dir / "t.webp");
    files.emplace_back("t.webp", test_support::Bytes(webp.begin(), webp.end()));
    const std::map<std::string, std::string> format{{"t.png", "PNG"}, {"t.jpg", "JPEG"},  {"t.bmp", "BMP"},
                                                    {"t.tga", "TGA"}, {"rle.tga", "TGA"}, {"t.webp", "WebP"}};
    for (const auto& [name, bytes] : files) {
        test_support::write_text(dir / name, std::string(bytes.begin(), bytes.end()));
        EXPECT_EQ(texture_error(dir / name), "") << name;  // whole, it reads
        test_support::write_text(
            dir / ("cut-" + name),
            std::string(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(bytes.size() * 3 / 5)));
        EXPECT_EQ(texture_error(dir / ("cut-" + name)), (dir / ("cut-" + name)).string() + ": truncated image: the " +
                                                            format.at(name) + " data ends before the picture does");
    }
    // A TGA header alone that claims 4000 x 4000 texels: stb_image would fill them with black.
    const std::string header{
        0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, static_cast<char>(0xa0), 0x0f, static_cast<char>(0xa0), 0x0f, 24, 0x20};
    test_support::write_text(dir / "header.tga", header);
    EXPECT_EQ(texture_error(dir / "header.tga"),
              (dir / "header.tga").string() + ": truncated image: the TGA data ends before the picture does");
}

TEST(TextureFile, APngHeaderClaimingMoreTexelsThanAllowedSaysItsSize) {
    const test_support::ScratchDir dir;
    const test_support::Bytes small = test_support::encode_png(test_support::Bytes(3 * 4, 0), 2, 2, 3);
    std::string png(small.begin(), small.end());
    png.replace(16, 8,
                std::string{0, 0, static_cast<char>(0xff), static_cast<char>(0xff), 0, 0, static_cast<char>(0xff),
                            static_cast<char>(0xff)});
    test_support::write_text(dir / "huge.png", png);
    EXPECT_EQ(texture_error(dir / "huge.png"),
              (dir / "huge.png").string() + ": image is 65535x65535, more than the 16777216 texels allowed");
}
