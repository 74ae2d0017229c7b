#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/scratch.hpp"

#include <limits>
#include <stdexcept>
#include <gtest/gtest.h>

using raster::AnimationWriter;
using raster::Framebuffer;
using test_support::ScratchDir;

namespace {

Framebuffer gradient(int width, int height, int seed) {
    Framebuffer image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.set_pixel(x, y,
                            {static_cast<std::uint8_t>(x * 7 + seed), static_cast<std::uint8_t>(y * 13),
                             static_cast<std::uint8_t>((x ^ y) + seed * 3)});
        }
    }
    return image;
}

}  // namespace

TEST(WebpStill, DecodesToTheExactPixelsAtEveryEffort) {
    const ScratchDir dir;
    const Framebuffer image = gradient(37, 23, 5);
    for (const raster::Effort effort : {raster::Effort::fast, raster::Effort::balanced, raster::Effort::max}) {
        const auto bytes = raster::write_webp_still(image, dir / "still.webp", effort);
        EXPECT_EQ(bytes, std::filesystem::file_size(dir / "still.webp"));
        const raster::DecodedWebp decoded = raster::read_webp(dir / "still.webp");
        EXPECT_EQ(decoded.width, 37);
        EXPECT_EQ(decoded.height, 23);
        ASSERT_EQ(decoded.frames.size(), 1U);
        EXPECT_EQ(decoded.frames[0].image, image);
    }
}

TEST(WebpAnimation, KeepsEveryFrameLosslessWithEvenlySpacedTimestamps) {
    const ScratchDir dir;
    AnimationWriter writer(dir / "anim.webp", 31, 17, raster::kFrameSpacingMs);
    std::vector<Framebuffer> frames;
    for (int i = 0; i < 5; ++i) {
        frames.push_back(gradient(31, 17, i * 11));
        writer.add_frame(frames.back());
    }
    writer.finish();
    const raster::DecodedWebp decoded = raster::read_webp(dir / "anim.webp");
    ASSERT_EQ(decoded.frames.size(), 5U);
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(decoded.frames[i].start_ms, i * 20) << "frame " << i;
        EXPECT_EQ(decoded.frames[i].duration_ms, 20) << "frame " << i;
        EXPECT_EQ(decoded.frames[i].image, frames[i]) << "frame " << i;
    }
}

TEST(WebpAnimation, BadDestinationFailsBeforeAnyFrameIsAdded) {
    const ScratchDir dir;
    EXPECT_THROW(AnimationWriter(dir / "missing" / "anim.webp", 8, 8, 20), std::runtime_error);
    EXPECT_THROW(AnimationWriter(dir.path(), 8, 8, 20), std::runtime_error);
}

TEST(WebpAnimation, UnfinishedWriterLeavesTheExistingFileAndNoTemporaryFile) {
    const ScratchDir dir;
    test_support::write_text(dir / "anim.webp", "keep me");
    {
        AnimationWriter writer(dir / "anim.webp", 8, 8, 20);
        writer.add_frame(Framebuffer(8, 8));
    }
    EXPECT_EQ(test_support::read_text(dir / "anim.webp"), "keep me");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"anim.webp"});
}

TEST(WebpAnimation, RejectsFramesOfAnotherSize) {
    const ScratchDir dir;
    AnimationWriter writer(dir / "anim.webp", 8, 8, 20);
    EXPECT_THROW(writer.add_frame(Framebuffer(9, 8)), std::invalid_argument);
}

TEST(WebpStill, FinishedWriteReplacesTheFileAndLeavesNoTemporaryFile) {
    const ScratchDir dir;
    test_support::write_text(dir / "still.webp", "old");
    raster::write_webp_still(gradient(4, 4, 1), dir / "still.webp");
    EXPECT_EQ(raster::read_webp(dir / "still.webp").frames.at(0).image, gradient(4, 4, 1));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"still.webp"});
}

TEST(WebpRead, RejectsFilesThatAreNotWebp) {
    const ScratchDir dir;
    test_support::write_text(dir / "fake.webp", "RIFF....WEBPnot really");
    EXPECT_THROW((void)raster::read_webp(dir / "fake.webp"), std::runtime_error);
    EXPECT_THROW((void)raster::read_webp(dir / "absent.webp"), std::runtime_error);
}

TEST(WebpAnimation, TimestampsStopWithAnErrorBeforeTheyWouldOverflow) {
    raster::AnimationEncoder encoder(1, 1, raster::kMaxFrameSpacingMs, raster::Effort::fast);
    const Framebuffer pixel(1, 1);
    for (int i = 0; i < 128; ++i) encoder.add_frame(pixel);  // 128 frames end at 2,147,483,520 ms
    EXPECT_THROW(encoder.add_frame(pixel), std::length_error) << "the 129th would end past 2^31 - 1 ms";
    const std::vector<std::uint8_t> bytes = encoder.finish();
    EXPECT_GT(bytes.size(), 0U);
}

TEST(WebpAnimation, RejectsSpacingsAndSizesWebpCannotStore) {
    for (const int spacing : {0, -20, raster::kMaxFrameSpacingMs + 1, std::numeric_limits<int>::max()}) {
        EXPECT_THROW(raster::AnimationEncoder(8, 8, spacing), std::invalid_argument) << spacing;
    }
    for (const auto& [width, height] : {std::pair{0, 8}, {8, -1}, {raster::kMaxImageSide + 1, 8}}) {
        EXPECT_THROW(raster::AnimationEncoder(width, height, 20), std::invalid_argument) << width << "x" << height;
    }
}

TEST(WebpAnimation, EncoderBytesDecodeLikeTheWrittenFile) {
    const ScratchDir dir;
    raster::AnimationEncoder encoder(6, 5, 40, raster::Effort::fast);
    AnimationWriter writer(dir / "anim.webp", 6, 5, 40, raster::Effort::fast);
    for (int i = 0; i < 3; ++i) {
        encoder.add_frame(gradient(6, 5, i));
        writer.add_frame(gradient(6, 5, i));
    }
    const std::vector<std::uint8_t> bytes = encoder.finish();
    EXPECT_EQ(writer.finish(), bytes.size());
    EXPECT_EQ(test_support::read_text(dir / "anim.webp"), std::string(bytes.begin(), bytes.end()));
}
