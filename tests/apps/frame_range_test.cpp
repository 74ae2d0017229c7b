// Frame ranges, restarts and assembly share one clip and its parts; stays whole so they read in order.
// Frame ranges, restartable runs and lossless assembly, as a render farm runs them.
#include <raster/io/webp.hpp>
#include <raster/io/webp_parts.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using test_support::kAnimatedCube;
using test_support::kAnimatedScene;
using test_support::kRender;
using test_support::kWebpAssemble;
using test_support::run;
using test_support::ScratchDir;

namespace {

const std::vector<std::string> kSmall{"--width", "64", "--height", "48", "--effort", "fast", "--quiet"};
const std::vector<std::string> kSaid{"--width", "64", "--height", "48", "--effort", "fast"};  // with the report line

std::vector<std::string> with(std::vector<std::string> arguments, const std::vector<std::string>& more) {
    arguments.insert(arguments.end(), more.begin(), more.end());
    return arguments;
}

std::vector<std::uint8_t> bytes_of(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Frame for frame, pixels and timing.
void expect_same_frames(const raster::DecodedWebp& actual, const raster::DecodedWebp& expected) {
    ASSERT_EQ(actual.frames.size(), expected.frames.size());
    for (std::size_t i = 0; i < expected.frames.size(); ++i) {
        EXPECT_EQ(actual.frames[i].image, expected.frames[i].image) << "frame " << i;
        EXPECT_EQ(actual.frames[i].start_ms, expected.frames[i].start_ms) << "frame " << i;
        EXPECT_EQ(actual.frames[i].duration_ms, expected.frames[i].duration_ms) << "frame " << i;
    }
}

}  // namespace

TEST(FrameRange, PartsRenderTheWholeRunsFramesAndAssembleToItExactly) {
    const ScratchDir dir;
    for (const std::string encoder : {"parallel", "anim"}) {
        const auto scene = with(kSmall, {"--scene", "islands", "--frames", "12", "--encoder", encoder});
        ASSERT_EQ(run(kAnimatedScene, with(scene, {"whole.webp"}), dir.path()).exit_code, 0);
        // Options before, between and after the names, both spellings of a range.
        ASSERT_EQ(run(kAnimatedScene, with(scene, {"--frame-range", "0..3", "a.webp"}), dir.path()).exit_code, 0);
        ASSERT_EQ(run(kAnimatedScene, with({"b.webp", "--frame-range=4:10"}, scene), dir.path()).exit_code, 0);
        ASSERT_EQ(run(kAnimatedScene, with(scene, {"c.webp", "--frame-range", "11..11"}), dir.path()).exit_code, 0);
        const raster::DecodedWebp whole = raster::read_webp(dir / "whole.webp");
        const raster::DecodedWebp b = raster::read_webp(dir / "b.webp");
        ASSERT_EQ(b.frames.size(), 7U);
        for (std::size_t i = 0; i < 7; ++i)
            EXPECT_EQ(b.frames[i].image, whole.frames[4 + i].image) << encoder << " frame " << 4 + i;
        EXPECT_EQ(raster::frame_range_of(bytes_of(dir / "b.webp")), (raster::FrameRange{4, 10, 12, 20}));
        EXPECT_EQ(raster::frame_range_of(bytes_of(dir / "whole.webp")), std::nullopt);

        const auto joined = run(kWebpAssemble, {"joined.webp", "c.webp", "a.webp", "b.webp"}, dir.path());
        ASSERT_EQ(joined.exit_code, 0) << joined.err;
        EXPECT_EQ(joined.out.rfind("Wrote joined.webp: 12 frames from 3 parts, ", 0), 0U) << joined.out;
        expect_same_frames(raster::read_webp(dir / "joined.webp"), whole);
        for (const char* name : {"whole.webp", "a.webp", "b.webp", "c.webp", "joined.webp"})
            std::filesystem::remove(dir / name);
    }
}

TEST(FrameRange, NumberedFramesOfARangeAreTheWholeRunsFiles) {
    const ScratchDir dir;
    const auto turn = with(kSmall, {"--frames", "9"});
    ASSERT_EQ(run(kAnimatedCube, with(turn, {"--frames-dir", "all"}), dir.path()).exit_code, 0);
    const auto part = run(kAnimatedCube, with(turn, {"--frames-dir", "some", "--frame-range", "3..5"}), dir.path());
    ASSERT_EQ(part.exit_code, 0) << part.err;
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "some"))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"0003.png", "0004.png", "0005.png"}));
    for (const std::string& name : names)
        EXPECT_EQ(bytes_of(dir / "some" / name), bytes_of(dir / "all" / name)) << name;
}

TEST(FrameRange, ATurntableRendersItsRangeToo) {
    const ScratchDir dir;
    const std::string model = test_support::write_crate_on_floor(dir.path()).string();
    const auto spin = with(kSmall, {"--turntable", "6", model});
    ASSERT_EQ(run(kRender, with(spin, {"whole.webp"}), dir.path()).exit_code, 0);
    const auto part = run(kRender, with(spin, {"part.webp", "--frame-range", "2..3"}), dir.path());
    ASSERT_EQ(part.exit_code, 0) << part.err;
    const raster::DecodedWebp whole = raster::read_webp(dir / "whole.webp"),
                              some = raster::read_webp(dir / "part.webp");
    ASSERT_EQ(some.frames.size(), 2U);
    EXPECT_EQ(some.frames[0].image, whole.frames[2].image);
    EXPECT_EQ(some.frames[1].image, whole.frames[3].image);
}

TEST(FrameRange, ARangeOutsideTheClipOrMalformedIsOneLine) {
    const ScratchDir dir;
    const auto past =
        run(kAnimatedCube, with(kSmall, {"--frames", "10", "--frame-range", "5..10", "x.webp"}), dir.path());
    EXPECT_EQ(past.exit_code, 1);
    EXPECT_EQ(past.err, "animated-cube: --frame-range 5..10 goes past the clip's last frame, 9\n");
    for (const std::string bad : {"3..1", "-1..4", "4", "a..b", "1...2", "1..", "99999999999..1"}) {
        const auto result = run(kAnimatedCube, with(kSmall, {"--frame-range", bad, "x.webp"}), dir.path());
        EXPECT_EQ(result.exit_code, 2) << bad;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "x.webp"));
}

TEST(WebpAssemble, RefusesPartsThatDoNotTileTheClipInOneLine) {
    const ScratchDir dir;
    const auto cube = with(kSmall, {"--frames", "10"});
    for (const auto& [name, range] : std::vector<std::pair<std::string, std::string>>{
             {"a.webp", "0..3"}, {"b.webp", "4..9"}, {"c.webp", "3..6"}, {"d.webp", "6..9"}}) {
        ASSERT_EQ(run(kAnimatedCube, with(cube, {"--frame-range", range, name}), dir.path()).exit_code, 0);
    }
    ASSERT_EQ(run(kAnimatedCube,
                  with({"--width", "32", "--height", "48", "--frames", "10", "--quiet", "--frame-range", "4..9"},
                       {"small.webp"}),
                  dir.path())
                  .exit_code,
              0);
    ASSERT_EQ(run(kAnimatedCube, with(kSmall, {"--frames", "20", "--frame-range", "4..9", "other.webp"}), dir.path())
                  .exit_code,
              0);
    ASSERT_EQ(run(kAnimatedCube, with(kSmall, {"--frames", "10", "whole.webp"}), dir.path()).exit_code, 0);
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"a.webp"}, "webp-assemble: frames 4..9 are in no part\n"},
        {{"b.webp"}, "webp-assemble: frames 0..3 are in no part\n"},
        {{"a.webp", "c.webp", "b.webp"}, "webp-assemble: 'c.webp' repeats frame 3\n"},
        {{"b.webp", "a.webp", "b.webp"}, "webp-assemble: 'b.webp' repeats frames 4..9\n"},
        {{"a.webp", "d.webp"}, "webp-assemble: frames 4..5 are in no part\n"},
        {{"a.webp", "small.webp"}, "webp-assemble: 'small.webp' is 32x48, the others 64x48\n"},
        {{"a.webp", "other.webp"}, "webp-assemble: 'other.webp' is part of a clip of 20 frames, 'a.webp' of 10\n"},
        {{"whole.webp"},
         "webp-assemble: 'whole.webp' is not a part: it has no frame range (render it with --frame-range)\n"},
        {{"a.webp", "missing.webp"}, "webp-assemble: 'missing.webp' does not exist\n"},
    };
    for (const auto& [parts, message] : cases) {
        const auto result = run(kWebpAssemble, with({"out.webp"}, parts), dir.path());
        EXPECT_EQ(result.exit_code, 1) << result.err;
        EXPECT_EQ(result.err, message);
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.webp"));
    }
    const std::vector<std::uint8_t> before = bytes_of(dir / "a.webp");
    EXPECT_EQ(run(kWebpAssemble, {"a.webp", "a.webp", "b.webp"}, dir.path()).exit_code, 1);  // never over a part
    EXPECT_EQ(bytes_of(dir / "a.webp"), before);
}

TEST(SkipExisting, ACompleteOutputIsKeptAndAnythingElseIsRendered) {
    const ScratchDir dir;
    const auto part = with(kSmall, {"--frames", "10", "--frame-range", "2..5", "--skip-existing"});
    ASSERT_EQ(run(kAnimatedCube, with(part, {"p.webp"}), dir.path()).exit_code, 0);
    const auto written = std::filesystem::last_write_time(dir / "p.webp");
    const auto again = run(kAnimatedCube,
                           with({"--frames", "10", "--frame-range", "2..5", "--skip-existing", "p.webp", "--width",
                                 "64", "--height", "48"},
                                {}),
                           dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.out, "Skipped p.webp: it already holds frames 2..5 of 10\n");
    EXPECT_EQ(std::filesystem::last_write_time(dir / "p.webp"), written);
    // Another range, another size, or a damaged file under the same name is rendered again.
    const auto other =
        run(kAnimatedCube, with(kSmall, {"--frames", "10", "--frame-range", "2..6", "--skip-existing", "p.webp"}),
            dir.path());
    ASSERT_EQ(other.exit_code, 0) << other.err;
    EXPECT_EQ(raster::frame_range_of(bytes_of(dir / "p.webp")), (raster::FrameRange{2, 6, 10, 20}));
    std::filesystem::resize_file(dir / "p.webp", 100);
    ASSERT_EQ(run(kAnimatedCube, with(kSmall, {"--frames", "10", "--frame-range", "2..6", "--skip-existing", "p.webp"}),
                  dir.path())
                  .exit_code,
              0);
    EXPECT_EQ(raster::read_webp(dir / "p.webp").frames.size(), 5U);
    // Numbered frames: only the missing ones are drawn.
    ASSERT_EQ(run(kAnimatedCube, with(kSmall, {"--frames", "6", "--frames-dir", "f"}), dir.path()).exit_code, 0);
    std::filesystem::remove(dir / "f" / "0002.png");
    const auto before = std::filesystem::last_write_time(dir / "f" / "0003.png");
    const auto refill =
        run(kAnimatedCube, {"--frames", "6", "--frames-dir", "f", "--skip-existing", "--width", "64", "--height", "48"},
            dir.path());
    ASSERT_EQ(refill.exit_code, 0) << refill.err;
    EXPECT_NE(refill.out.find(": 1 PNG frames of 64x48"), std::string::npos) << refill.out;
    EXPECT_NE(refill.out.find("5 already there kept"), std::string::npos) << refill.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "f" / "0002.png"));
    EXPECT_EQ(std::filesystem::last_write_time(dir / "f" / "0003.png"), before);
}

TEST(SkipExisting, ABatchDrawsOnlyTheModelsWhosePicturesAreMissing) {
    const ScratchDir dir;
    const std::string crate = test_support::write_crate_on_floor(dir.path()).string();
    std::filesystem::copy_file(crate, dir / "second.obj");
    const std::vector<std::string> batch{"--width",      "32", "--height", "24",
                                         "--output-dir", "t",  crate,      (dir / "second.obj").string()};
    ASSERT_EQ(run(kRender, batch, dir.path()).exit_code, 0);
    std::filesystem::remove(dir / "t" / "second.webp");
    const auto kept = std::filesystem::last_write_time(dir / "t" / std::filesystem::path(crate).stem().concat(".webp"));
    const auto again = run(kRender, with(batch, {"--skip-existing"}), dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_NE(again.out.find("Rendered 1 of 1 models into t in "), std::string::npos) << again.out;
    EXPECT_NE(again.out.find(", 1 already there kept"), std::string::npos) << again.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "t" / "second.webp"));
    EXPECT_EQ(std::filesystem::last_write_time(dir / "t" / std::filesystem::path(crate).stem().concat(".webp")), kept);
}

TEST(FrameRange, ATransparentTurntableWhoseFramesLibwebpMergesStillAssembles) {
    // A cube turned a quarter at a time looks the same every frame: libwebp's anim encoder,
    // which transparency takes, stores one frame lasting the whole part.
    const ScratchDir dir;
    std::ofstream(dir / "cube.obj")
        << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";
    const auto spin = with(kSaid, {"--turntable", "4", "--background", "none", "cube.obj"});
    ASSERT_EQ(run(kRender, with(spin, {"whole.webp"}), dir.path()).exit_code, 0);
    ASSERT_EQ(run(kRender, with(spin, {"--frame-range", "0..1", "p0.webp"}), dir.path()).exit_code, 0);
    EXPECT_EQ(raster::webp_frame_count(bytes_of(dir / "p0.webp")), 1)
        << "the case this test is about: two frames merged into one";
    ASSERT_EQ(run(kRender, with(spin, {"--frame-range", "2..3", "p1.webp"}), dir.path()).exit_code, 0);
    const auto joined = run(kWebpAssemble, {"joined.webp", "p0.webp", "p1.webp"}, dir.path());
    ASSERT_EQ(joined.exit_code, 0) << joined.err;
    const raster::DecodedWebp whole = raster::read_webp(dir / "whole.webp"),
                              both = raster::read_webp(dir / "joined.webp");
    ASSERT_FALSE(whole.frames.empty());
    // The whole run merged all four into a still; the join shows the same picture for 4 x 33 ms.
    EXPECT_EQ(both.frames.back().start_ms + both.frames.back().duration_ms, 132);
    for (const raster::DecodedFrame& frame : both.frames) EXPECT_EQ(frame.image, whole.frames.front().image);
    // A finished part is recognised as such, merged frames and all.
    const auto again = run(kRender, with(spin, {"--frame-range", "0..1", "--skip-existing", "p0.webp"}), dir.path());
    EXPECT_EQ(again.out.rfind("Skipped p0.webp", 0), 0U) << again.out << again.err;
}

TEST(SkipExisting, APartOfAnotherSceneOrRateIsRenderedAgain) {
    const ScratchDir dir;
    const auto clip = with(kSaid, {"--frames", "6", "--frame-range", "0..1", "--skip-existing", "p.webp"});
    ASSERT_EQ(run(kAnimatedScene, clip, dir.path()).exit_code, 0);
    const auto islands = run(kAnimatedScene, with(clip, {"--scene", "islands"}), dir.path());
    EXPECT_EQ(islands.out.find("Skipped"), std::string::npos) << islands.out;
    const auto slower = run(kAnimatedScene, with(clip, {"--scene", "islands", "--fps", "10"}), dir.path());
    EXPECT_EQ(slower.out.find("Skipped"), std::string::npos) << slower.out;
    const auto same = run(kAnimatedScene, with(clip, {"--scene", "islands", "--fps", "10"}), dir.path());
    EXPECT_EQ(same.out.rfind("Skipped p.webp", 0), 0U) << same.out;
}
