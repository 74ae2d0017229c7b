#include <raster/io/output_file.hpp>
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/scratch.hpp"
#include "support/webp_files.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>
#include <gtest/gtest.h>

using raster::Framebuffer;
using test_support::kAnimatedCube;
using test_support::kWebpFrames;
using test_support::read_bytes;
using test_support::run;
using test_support::ScratchDir;

TEST(WebpFramesApp, WritesEveryFrameAsTheNumberedPngAPlayerShows) {
    const ScratchDir dir;
    ASSERT_EQ(
        run(kAnimatedCube, {"--frames", "12", "--width", "96", "--height", "72", "spin.webp"}, dir.path()).exit_code,
        0);
    const auto result = run(kWebpFrames, {"spin.webp", "frames"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err, "");
    EXPECT_EQ(result.out.rfind("Wrote frames/0000.png to 0011.png: 12 frames of 96x72, 20 ms each, ", 0), 0U)
        << result.out;
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
    EXPECT_EQ(result.out.rfind("Wrote f/0000.png to 0001.png: 2 frames of 8x8, lasting 20 to 40 ms, ", 0), 0U)
        << result.out;
}

TEST(WebpFramesApp, MistakesAreOneLineAndTheInputIsNeverReplaced) {
    const ScratchDir dir;
    test_support::write_text(dir / "fake.webp", "not a picture");
    const auto fake = run(kWebpFrames, {"fake.webp", "f"}, dir.path());
    EXPECT_EQ(fake.exit_code, 1);
    EXPECT_EQ(std::count(fake.err.begin(), fake.err.end(), '\n'), 1) << fake.err;
    EXPECT_EQ(run(kWebpFrames, {"fake.webp"}, dir.path()).exit_code, 2);
    ASSERT_EQ(run(kAnimatedCube, {"--frames", "2", "--width", "8", "--height", "8", "0000.png", "--format", "webp"},
                  dir.path())
                  .exit_code,
              0);
    const std::vector<std::uint8_t> before = read_bytes(dir / "0000.png");
    const auto over = run(kWebpFrames, {"0000.png", "."}, dir.path());
    EXPECT_EQ(over.exit_code, 1);
    EXPECT_EQ(read_bytes(dir / "0000.png"), before);
}

TEST(WebpFramesApp, AnyFrameFileAlreadyThereIsRefusedAndNothingIsWritten) {
    const ScratchDir dir;
    ASSERT_EQ(
        run(kAnimatedCube, {"--frames", "12", "--width", "32", "--height", "24", "--quiet", "spin.webp"}, dir.path())
            .exit_code,
        0);
    std::filesystem::create_directory(dir / "frames");
    test_support::write_text(dir / "frames" / "0007.png", "someone else's frame");
    const auto seventh = run(kWebpFrames, {"spin.webp", "frames"}, dir.path());
    EXPECT_EQ(seventh.exit_code, 1);
    EXPECT_EQ(seventh.err, "webp-frames: 'frames' already holds frames (0007.png); choose an empty directory\n");
    EXPECT_EQ(test_support::read_text(dir / "frames" / "0007.png"), "someone else's frame");
    std::filesystem::remove(dir / "frames" / "0007.png");
    // A link that leads nowhere is in the way too: a frame written through it would land elsewhere.
    std::filesystem::create_symlink(dir / "nowhere.png", dir / "frames" / "0011.png");
    const auto dangling = run(kWebpFrames, {"spin.webp", "frames"}, dir.path());
    EXPECT_EQ(dangling.exit_code, 1);
    EXPECT_EQ(dangling.err, "webp-frames: 'frames' already holds frames (0011.png); choose an empty directory\n");
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "frames"))
        left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"0011.png"});
    EXPECT_FALSE(std::filesystem::exists(dir / "nowhere.png"));
}

TEST(WebpFramesApp, AFrameThatDoesNotDecodeLeavesNoFramesAndNoTemporaryDirectory) {
    const ScratchDir dir;
    // Four whole frames, the third's picture damaged past its header: it fails only when decoded.
    const test_support::HandFrame whole{0, 0, 8, 8, 20, 2, test_support::vp8l_chunk(8, 8)};
    std::vector<test_support::HandFrame> frames(4, whole);
    // The VP8L chunk cut to its 5-byte header and one byte of pixels.
    frames[2].picture = test_support::riff_chunk("VP8L", {whole.picture.begin() + 8, whole.picture.begin() + 14});
    raster::write_output_file(dir / "broken.webp", test_support::animated_webp(8, 8, frames));
    const auto result = run(kWebpFrames, {"broken.webp", "frames"}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err.rfind("webp-frames: 'broken.webp' has a corrupt frame 2: ", 0), 0U) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir / "frames"));
}
