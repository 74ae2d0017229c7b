// WebpFrameReader: frames composited onto one canvas exactly as libwebp's own animation decoder
// composites them, and timestamps that add up past 2^31 ms.
#include <raster/io/output_file.hpp>
#include <raster/io/webp.hpp>

#include "support/scratch.hpp"
#include "support/webp_files.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>
#include <webp/demux.h>

using test_support::HandFrame;
using test_support::ScratchDir;

TEST(WebpRead, FramesMatchLibwebpsAnimationDecoderPixelForPixel) {
    // Every blend and dispose combination, over rectangles that overlap, in partly transparent frames.
    const ScratchDir dir;
    constexpr int kWidth = 16, kHeight = 12;
    std::uint32_t seed = 12345;
    const auto random = [&](std::uint32_t below) {
        seed = seed * 1664525U + 1013904223U;
        return (seed >> 8) % below;
    };
    std::vector<HandFrame> frames;
    for (int k = 0; k < 40; ++k) {
        HandFrame frame;
        const bool whole = random(4) == 0;
        frame.x = whole ? 0 : static_cast<int>(random(kWidth / 2)) * 2;
        frame.y = whole ? 0 : static_cast<int>(random(kHeight / 2)) * 2;
        frame.width = whole ? kWidth : 1 + static_cast<int>(random(static_cast<std::uint32_t>(kWidth - frame.x)));
        frame.height = whole ? kHeight : 1 + static_cast<int>(random(static_cast<std::uint32_t>(kHeight - frame.y)));
        frame.duration_ms = 10 + k;
        frame.flags = static_cast<std::uint8_t>(random(4));
        raster::Framebuffer image(frame.width, frame.height);
        std::vector<std::uint8_t> alpha(static_cast<std::size_t>(frame.width * frame.height));
        const bool opaque = random(3) == 0;
        for (int y = 0; y < frame.height; ++y) {
            for (int x = 0; x < frame.width; ++x) {
                image.set_pixel(x, y,
                                {static_cast<std::uint8_t>(random(256)), static_cast<std::uint8_t>(random(256)),
                                 static_cast<std::uint8_t>(random(256))});
                const std::uint32_t level = random(4);
                alpha[static_cast<std::size_t>(y * frame.width + x)] =
                    opaque ? 255
                           : static_cast<std::uint8_t>(level == 0   ? 0
                                                       : level == 1 ? 255
                                                                    : random(256));
            }
        }
        frame.picture = test_support::vp8l_chunk(image, alpha);
        frames.push_back(frame);
    }
    const std::vector<std::uint8_t> bytes = test_support::animated_webp(kWidth, kHeight, frames);
    raster::write_output_file(dir / "mixed.webp", bytes);

    const WebPData data{bytes.data(), bytes.size()};
    WebPAnimDecoderOptions options;
    ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
    options.color_mode = MODE_RGBA;
    const std::unique_ptr<WebPAnimDecoder, void (*)(WebPAnimDecoder*)> libwebp(WebPAnimDecoderNew(&data, &options),
                                                                               WebPAnimDecoderDelete);
    ASSERT_TRUE(libwebp);
    int index = 0;
    const raster::WebpInfo info =
        raster::for_each_webp_frame(dir / "mixed.webp", [&](const raster::DecodedFrame& frame) {
            std::uint8_t* rgba = nullptr;
            int end_ms = 0;
            EXPECT_TRUE(WebPAnimDecoderGetNext(libwebp.get(), &rgba, &end_ms));
            for (std::size_t i = 0; i < static_cast<std::size_t>(kWidth * kHeight); ++i) {
                const std::uint8_t* ours = frame.image.bytes().data() + i * 3;
                const bool same = ours[0] == rgba[i * 4] && ours[1] == rgba[i * 4 + 1] && ours[2] == rgba[i * 4 + 2] &&
                                  frame.alpha[i] == rgba[i * 4 + 3];
                EXPECT_TRUE(same) << "frame " << index << " pixel " << i;
                if (!same) return false;
            }
            EXPECT_EQ(frame.start_ms + frame.duration_ms, end_ms) << "frame " << index;
            ++index;
            return true;
        });
    EXPECT_EQ(index, 40);
    EXPECT_EQ(info.frame_count, 40);
}

TEST(WebpRead, StartTimesPastTwoToThe31MsAddUpExactly) {
    // 130 frames of the longest a WebP frame lasts, 2^24 - 1 ms, end past INT_MAX ms.
    const ScratchDir dir;
    const HandFrame longest{0, 0, 1, 1, raster::kMaxFrameSpacingMs, 2, test_support::vp8l_chunk(1, 1)};
    raster::write_output_file(dir / "long.webp",
                              test_support::animated_webp(1, 1, std::vector<HandFrame>(130, longest)));
    const raster::DecodedWebp decoded = raster::read_webp(dir / "long.webp");
    ASSERT_EQ(decoded.frames.size(), 130U);
    for (std::size_t i = 0; i < decoded.frames.size(); ++i) {
        EXPECT_EQ(decoded.frames[i].start_ms, static_cast<std::int64_t>(i) * raster::kMaxFrameSpacingMs)
            << "frame " << i;
        EXPECT_EQ(decoded.frames[i].duration_ms, raster::kMaxFrameSpacingMs) << "frame " << i;
    }
    EXPECT_GT(decoded.frames.back().start_ms, std::int64_t{std::numeric_limits<int>::max()});
}
