#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include <raster/io/output_file.hpp>

#include "support/scratch.hpp"
#include "support/webp_files.hpp"

#include "support/sanitizers.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

using raster::Framebuffer;
using test_support::kAnimatedCube;
using test_support::kWebpFrame;
using test_support::run;
using test_support::ScratchDir;

#ifndef RASTER_TEST_ASAN
namespace {

// webp-frame run with its address space limited to `mebibytes` (RLIMIT_AS, through ulimit -v).
test_support::RunResult run_limited(std::uint64_t mebibytes, const std::vector<std::string>& arguments,
                                    const std::filesystem::path& dir) {
    std::vector<std::string> shell{"-c", "ulimit -v " + std::to_string(mebibytes * 1024) + " && exec \"$0\" \"$@\"",
                                   kWebpFrame};
    shell.insert(shell.end(), arguments.begin(), arguments.end());
    return run("/bin/sh", shell, dir);
}

}  // namespace
#endif

TEST(WebpFrameApp, WritesFrameNAsTheWholePictureAPlayerShows) {
    const ScratchDir dir;
    ASSERT_EQ(
        run(kAnimatedCube, {"--frames", "12", "--width", "96", "--height", "72", "spin.webp"}, dir.path()).exit_code,
        0);
    Framebuffer expected(96, 72);
    for (const int index : {0, 5, 11}) {
        const std::string out = "frame-" + std::to_string(index) + ".webp";
        const auto result = run(kWebpFrame, {"spin.webp", std::to_string(index), out}, dir.path());
        EXPECT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(result.out.rfind("Wrote " + out + ": frame " + std::to_string(index) + " of spin.webp, 96x72, ", 0),
                  0U)
            << result.out;
        const raster::DecodedWebp still = raster::read_webp(dir / out);
        ASSERT_EQ(still.frames.size(), 1U);
        raster::render_tumble_frame(expected, index, 12, raster::CubeStyle::filled);
        EXPECT_EQ(still.frames[0].image, expected) << "frame " << index;
    }
}

TEST(WebpFrameApp, FrameZeroOfAStillIsTheStill) {
    const ScratchDir dir;
    Framebuffer image(5, 4);
    image.set_pixel(2, 1, {1, 2, 3});
    raster::write_webp_still(image, dir / "still.webp");
    EXPECT_EQ(run(kWebpFrame, {"still.webp", "0", "-o", "copy.webp"}, dir.path()).exit_code, 0);
    EXPECT_EQ(raster::read_webp(dir / "copy.webp").frames.at(0).image, image);
}

TEST(WebpFrameApp, DecodingHoldsOneCanvasAndOneFrameHoweverLargeTheCanvasClaims) {
#ifdef RASTER_TEST_ASAN
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space, so RLIMIT_AS cannot measure decoding here";
#else
    const ScratchDir dir;
    // A few dozen bytes: the largest canvas WebP allows and one 2x2 frame on it. libwebp's own
    // animation decoder held that canvas three to four times over (3.75 GiB).
    const test_support::HandFrame tiny{0, 0, 2, 2, 20, 2, test_support::vp8l_chunk(2, 2)};
    constexpr int kSide = raster::kMaxImageSide;
    raster::write_output_file(dir / "huge.webp", test_support::animated_webp(kSide, kSide, {tiny}));
    raster::write_output_file(dir / "small.webp", test_support::animated_webp(2, 2, {tiny}));
    // What the program needs besides the canvas: the least limit (to 8 MiB) that decodes the small one.
    const std::vector<std::string> past_the_end{"1", "out.webp"};
    const auto decodes = [&](const std::string& file, std::uint64_t mebibytes) {
        const auto result = run_limited(mebibytes, {file, past_the_end[0], past_the_end[1]}, dir.path());
        return result.exit_code == 1 && result.err == "webp-frame: '" + file + "' has 1 frame(s), numbered 0..0\n";
    };
    std::uint64_t low = 8, high = 1024;
    ASSERT_TRUE(decodes("small.webp", high));
    while (high - low > 8) {
        const std::uint64_t middle = (low + high) / 2;
        (decodes("small.webp", middle) ? high : low) = middle;
    }
    // One canvas at 4 bytes a pixel, and 32 MiB for the frame and the slack: well under two canvases.
    const std::uint64_t canvas = std::uint64_t{kSide} * kSide * 4 / (1024 * 1024);
    const std::uint64_t limit = high + canvas + 32;
    EXPECT_TRUE(decodes("huge.webp", limit))
        << "more than " << limit << " MiB, " << high << " MiB of it before any canvas";
    EXPECT_FALSE(std::filesystem::exists(dir / "out.webp"));
#endif
}
