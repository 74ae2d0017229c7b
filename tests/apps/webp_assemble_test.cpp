// webp-assemble against damaged parts, many frames and standard output.
#include <raster/io/output_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/io/webp_parts.hpp>

#include "support/scratch.hpp"
#include "support/webp_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using test_support::kAnimatedCube;
using test_support::kWebpAssemble;
using test_support::read_bytes;
using test_support::run;
using test_support::ScratchDir;

namespace {

const std::vector<std::string> kTen{"--width", "64", "--height", "48", "--effort", "fast", "--quiet", "--frames", "10"};

void render_parts(const ScratchDir& dir) {
    for (const auto& [name, range] : {std::pair{"a.webp", "0..3"}, std::pair{"b.webp", "4..9"}}) {
        std::vector<std::string> arguments = kTen;
        arguments.insert(arguments.end(), {"--frame-range", range, name});
        ASSERT_EQ(run(kAnimatedCube, arguments, dir.path()).exit_code, 0);
    }
}

// Two marked parts of `frames` whole 2x2 frames each, of a clip of 2 * frames at 20 ms.
std::vector<std::vector<std::uint8_t>> many_frame_parts(int frames) {
    test_support::HandFrame frame{0, 0, 2, 2, 20, 2, test_support::vp8l_chunk(2, 2)};
    const std::vector<test_support::HandFrame> all(static_cast<std::size_t>(frames), frame);
    std::vector<std::vector<std::uint8_t>> parts;
    for (int k = 0; k < 2; ++k) {
        const std::vector<std::uint8_t> marked = raster::mark_frame_range(
            test_support::animated_webp(2, 2, all), {k * frames, k * frames + frames - 1, 2 * frames, 20});
        parts.push_back(marked);
    }
    return parts;
}

}  // namespace

TEST(WebpAssemble, ACorruptFrameAfterAPartsFirstIsRefusedNamingThePartAndTheFrame) {
    const ScratchDir dir;
    render_parts(dir);
    const std::vector<std::uint8_t> good = read_bytes(dir / "b.webp");
    // b.webp's third frame is the clip's frame 6: its picture's signature byte, then its size, damaged.
    const std::size_t picture = test_support::find_tag(good, "ANMF", 2) + 8 + 16;
    ASSERT_EQ(std::string(good.begin() + static_cast<std::ptrdiff_t>(picture),
                          good.begin() + static_cast<std::ptrdiff_t>(picture) + 4),
              "VP8L");
    std::vector<std::uint8_t> bad = good;
    bad[picture + 8] = 0;
    raster::write_output_file(dir / "b.webp", bad);
    const auto unreadable = run(kWebpAssemble, {"out.webp", "a.webp", "b.webp"}, dir.path());
    EXPECT_EQ(unreadable.exit_code, 1);
    EXPECT_EQ(unreadable.err, "webp-assemble: 'b.webp' has a corrupt frame 6: its picture does not decode\n");
    bad = good;
    bad[picture + 9] ^= 0x01;  // the picture's width, one more or one less than its rectangle's
    raster::write_output_file(dir / "b.webp", bad);
    const auto misfit = run(kWebpAssemble, {"out.webp", "a.webp", "b.webp"}, dir.path());
    EXPECT_EQ(misfit.exit_code, 1);
    EXPECT_EQ(misfit.err.rfind("webp-assemble: 'b.webp' has a corrupt frame 6: its picture is ", 0), 0U) << misfit.err;
    EXPECT_EQ(std::count(misfit.err.begin(), misfit.err.end(), '\n'), 1) << misfit.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.webp"));
}

TEST(WebpAssemble, EightyThousandFramesJoinIntoOneClipInOrder) {
    // 2 x 40,000 frames took 87 s when each frame was looked up from the first; the times are in
    // doc/performance.md, since a test judges what is written, not the clock.
    const ScratchDir dir;
    const auto parts = many_frame_parts(40000);
    raster::write_output_file(dir / "a.webp", parts[0]);
    raster::write_output_file(dir / "b.webp", parts[1]);
    const auto joined = run(kWebpAssemble, {"clip.webp", "b.webp", "a.webp"}, dir.path());
    ASSERT_EQ(joined.exit_code, 0) << joined.err;
    EXPECT_EQ(joined.out.rfind("Wrote clip.webp: 80000 frames from 2 parts, ", 0), 0U) << joined.out;
    const raster::WebpInfo info = raster::for_each_webp_frame(
        dir / "clip.webp", [](const raster::DecodedFrame& frame) { return frame.start_ms == 0; });
    EXPECT_EQ(info.frame_count, 80000);
}

TEST(WebpAssemble, DashWritesTheClipToStandardOutput) {
    const ScratchDir dir;
    render_parts(dir);
    ASSERT_EQ(run(kWebpAssemble, {"--quiet", "file.webp", "a.webp", "b.webp"}, dir.path()).exit_code, 0);
    const auto piped = run(kWebpAssemble, {"-", "b.webp", "a.webp"}, dir.path());
    ASSERT_EQ(piped.exit_code, 0) << piped.err;
    const std::vector<std::uint8_t> file = read_bytes(dir / "file.webp");
    EXPECT_EQ(piped.out, std::string(file.begin(), file.end()));
    EXPECT_EQ(piped.err.rfind("Wrote standard output: 10 frames from 2 parts, ", 0), 0U) << piped.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "-"));
}
