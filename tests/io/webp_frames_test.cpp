#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/scratch.hpp"

#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>

using raster::Framebuffer;
using test_support::kAnimatedCube;
using test_support::kWebpFrames;
using test_support::read_bytes;
using test_support::run;
using test_support::ScratchDir;

TEST(WebpFramesApp, WritesEveryFrameAsTheNumberedPngAPlayerShows) {
    const ScratchDir dir;
    ASSERT_EQ(run(kAnimatedCube, {"--frames", "12", "--width", "96", "--height", "72", "spin.webp"}, dir.path()).exit_code, 0);
    const auto result = run(kWebpFrames, {"spin.webp", "frames"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err, "");
    EXPECT_EQ(result.out.rfind("Wrote frames/0000.png to 0011.png: 12 frames of 96x72, 20 ms each, ", 0), 0U) << result.out;
    Framebuffer expected(96, 72);
    for (int index = 0; index < 12; ++index) {
        char name[16];
        std::snprintf(name, sizeof name, "%04d.png", index);
        raster::render_tumble_frame(expected, index, 12, raster::CubeStyle::filled);
        const raster::DecodedPng png = raster::decode_png(read_bytes(dir / "frames" / name), 1 << 20);
        EXPECT_EQ(png.image, expected) << name;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "frames" / "0012.png"));
    // A directory that already holds frames is refused, so no stale frame follows ours.
    const auto again = run(kWebpFrames, {"spin.webp", "frames"}, dir.path());
    EXPECT_EQ(again.exit_code, 1);
    EXPECT_EQ(again.err, "webp-frames: 'frames' already holds frames (0000.png); choose an empty directory\n");
}

TEST(WebpFramesApp, SaysWhenFramesLastUnequallyLong) {
    const ScratchDir dir;
    Framebuffer a(8, 8), b(8, 8);
    b.set_pixel(3, 3, {200, 10, 10});
    raster::AnimationEncoder encoder(8, 8, 20, {raster::Effort::fast, raster::AnimationPath::anim});
    for (const Framebuffer* frame : {&a, &a, &b}) encoder.add_frame(*frame);  // libwebp merges the two a's
    const std::vector<std::uint8_t> bytes = encoder.finish();
    raster::write_output_file(dir / "uneven.webp", bytes);
    const auto result = run(kWebpFrames, {"uneven.webp", "f"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("Wrote f/0000.png to 0001.png: 2 frames of 8x8, lasting 20 to 40 ms, ", 0), 0U) << result.out;
}

TEST(WebpFramesApp, MistakesAreOneLineAndTheInputIsNeverReplaced) {
    const ScratchDir dir;
    test_support::write_text(dir / "fake.webp", "not a picture");
    const auto fake = run(kWebpFrames, {"fake.webp", "f"}, dir.path());
    EXPECT_EQ(fake.exit_code, 1);
    EXPECT_EQ(std::count(fake.err.begin(), fake.err.end(), '\n'), 1) << fake.err;
    EXPECT_EQ(run(kWebpFrames, {"fake.webp"}, dir.path()).exit_code, 2);
    ASSERT_EQ(run(kAnimatedCube, {"--frames", "2", "--width", "8", "--height", "8", "0000.png", "--format", "webp"}, dir.path()).exit_code, 0);
    const std::vector<std::uint8_t> before = read_bytes(dir / "0000.png");
    const auto over = run(kWebpFrames, {"0000.png", "."}, dir.path());
    EXPECT_EQ(over.exit_code, 1);
    EXPECT_EQ(read_bytes(dir / "0000.png"), before);
}
