// Every exporter run as a user would; stays whole so that the programs' shared behaviour reads side by side.
#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/scratch.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <sys/stat.h>

using raster::CubeStyle;
using raster::Framebuffer;
using test_support::kAnimatedCube;
using test_support::kStillCube;
using test_support::kStillUnitCube;
using test_support::kWebpFrame;
using test_support::run;
using test_support::ScratchDir;

namespace {

int line_count(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// A successful run prints exactly "Wrote <file>: <details>, <size> bytes" and nothing else.
void expect_reported(const test_support::RunResult& result, const std::string& file,
                     const std::filesystem::path& written) {
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err, "");
    EXPECT_EQ(line_count(result.out), 1) << result.out;
    EXPECT_EQ(result.out.rfind("Wrote " + file + ": ", 0), 0U) << result.out;
    EXPECT_NE(result.out.find(", " + std::to_string(std::filesystem::file_size(written)) + " bytes\n"),
              std::string::npos)
        << result.out;
}

Framebuffer still_cube(int width, int height, CubeStyle style) {
    Framebuffer image(width, height);
    raster::render_still_cube(image, style);
    return image;
}

}  // namespace

TEST(StillCubeApp, WritesTheFilledCubeToTheDefaultPath) {
    const ScratchDir dir;
    const auto result = run(kStillCube, {}, dir.path());
    expect_reported(result, "still-cube.webp", dir / "still-cube.webp");
    const raster::DecodedWebp decoded = raster::read_webp(dir / "still-cube.webp");
    ASSERT_EQ(decoded.frames.size(), 1U);
    EXPECT_EQ(decoded.frames[0].image, still_cube(800, 600, CubeStyle::filled));
}

TEST(StillCubeApp, EachStyleAndSizeDecodesToTheInMemoryRender) {
    const ScratchDir dir;
    for (const auto& [name, style] : {std::pair{"wireframe", CubeStyle::wireframe},
                                      {"culled-wireframe", CubeStyle::culled_wireframe},
                                      {"filled", CubeStyle::filled}}) {
        const auto result =
            run(kStillCube, {"--style", name, "--width", "321", "--height", "123", "out.webp"}, dir.path());
        expect_reported(result, "out.webp", dir / "out.webp");
        EXPECT_EQ(raster::read_webp(dir / "out.webp").frames.at(0).image, still_cube(321, 123, style)) << name;
    }
}

TEST(StillUnitCubeApp, WritesOneDeepBlueSquareInTheMiddle) {
    const ScratchDir dir;
    const auto result = run(kStillUnitCube, {"unit.webp"}, dir.path());
    expect_reported(result, "unit.webp", dir / "unit.webp");
    const Framebuffer image = raster::read_webp(dir / "unit.webp").frames.at(0).image;
    int min_x = 800, max_x = -1, min_y = 600, max_y = -1, blue = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb colour = image.pixel(x, y);
            if (colour == raster::Rgb{}) continue;
            ASSERT_EQ(colour, (raster::Rgb{0, 0, 255})) << "at (" << x << ", " << y << ")";
            ++blue;
            min_x = std::min(min_x, x), max_x = std::max(max_x, x);
            min_y = std::min(min_y, y), max_y = std::max(max_y, y);
        }
    }
    EXPECT_EQ(blue, (max_x - min_x + 1) * (max_y - min_y + 1)) << "blue pixels form a solid rectangle";
    EXPECT_EQ(max_x - min_x, max_y - min_y) << "and it is square";
    EXPECT_EQ(min_x + max_x, 799) << "centred horizontally";
    EXPECT_EQ(min_y + max_y, 599) << "centred vertically";
}

TEST(AnimatedCubeApp, Writes360LosslessFramesTwentyMillisecondsApart) {
    const ScratchDir dir;
    const auto result = run(kAnimatedCube, {}, dir.path());
    expect_reported(result, "animated-cube.webp", dir / "animated-cube.webp");
    EXPECT_NE(result.out.find("360 frames, 7200 ms"), std::string::npos) << result.out;
    const raster::DecodedWebp decoded = raster::read_webp(dir / "animated-cube.webp");
    EXPECT_EQ(decoded.width, 800);
    EXPECT_EQ(decoded.height, 600);
    ASSERT_EQ(decoded.frames.size(), 360U);
    Framebuffer expected(800, 600);
    for (int i = 0; i < 360; ++i) {
        const raster::DecodedFrame& frame = decoded.frames[static_cast<std::size_t>(i)];
        ASSERT_EQ(frame.start_ms, i * 20) << "frame " << i;
        ASSERT_EQ(frame.duration_ms, 20) << "frame " << i;
        raster::render_tumble_frame(expected, i, 360, CubeStyle::filled);
        ASSERT_EQ(frame.image, expected) << "frame " << i;
    }
    EXPECT_EQ(decoded.frames.back().start_ms + decoded.frames.back().duration_ms, 7200);
}

TEST(AnimatedCubeApp, HonoursFramesFpsStyleSizeAndEffort) {
    const ScratchDir dir;
    const auto result = run(kAnimatedCube,
                            {"--frames", "12", "--fps", "25", "--style", "culled-wireframe", "--width", "160",
                             "--height", "90", "--effort", "fast", "spin.webp"},
                            dir.path());
    expect_reported(result, "spin.webp", dir / "spin.webp");
    const raster::DecodedWebp decoded = raster::read_webp(dir / "spin.webp");
    ASSERT_EQ(decoded.frames.size(), 12U);
    Framebuffer expected(160, 90);
    for (int i = 0; i < 12; ++i) {
        EXPECT_EQ(decoded.frames[static_cast<std::size_t>(i)].start_ms, i * 40);
        raster::render_tumble_frame(expected, i, 12, CubeStyle::culled_wireframe);
        EXPECT_EQ(decoded.frames[static_cast<std::size_t>(i)].image, expected) << "frame " << i;
    }
}

TEST(ExporterApps, HelpTeachesTheOptionsAndSucceeds) {
    const ScratchDir dir;
    for (const std::string& app :
         {kStillCube, kAnimatedCube, kStillUnitCube, test_support::kStillScene, test_support::kAnimatedScene}) {
        const auto result = run(app, {"--help"}, dir.path());
        EXPECT_EQ(result.exit_code, 0);
        for (const char* option : {"--width", "--height", "--effort", "output", "Example"}) {
            EXPECT_NE(result.out.find(option), std::string::npos) << app << " lacks " << option;
        }
    }
    EXPECT_NE(run(kAnimatedCube, {"--help"}, dir.path()).out.find("--frames"), std::string::npos);
    EXPECT_NE(run(kStillCube, {"--help"}, dir.path()).out.find("culled-wireframe"), std::string::npos);
}

struct BadInput {
    std::string case_name;
    std::string app;
    std::vector<std::string> arguments;
    std::string message;
    bool usage_error = true;  // exit code 2; other failures exit 1
};

void PrintTo(const BadInput& bad, std::ostream* out) { *out << bad.case_name; }

class ExporterRejects : public ::testing::TestWithParam<BadInput> {};

TEST_P(ExporterRejects, WithOneLineANonZeroExitAndTheExistingFileUntouched) {
    const ScratchDir dir;
    test_support::write_text(dir / "existing.webp", "precious");
    test_support::write_text(dir / "a-file", "");
    ASSERT_EQ(::mkfifo((dir / "a-fifo").c_str(), 0600), 0);
    std::filesystem::create_symlink("existing.webp", dir / "a-link.webp");
    raster::AnimationWriter two_frames(dir / "two-frames.webp", 4, 4, 20, raster::Effort::fast);
    Framebuffer frame(4, 4);
    two_frames.add_frame(frame);
    frame.set_pixel(1, 1, raster::Rgb{255, 255, 255});  // identical frames would merge into one
    two_frames.add_frame(frame);
    two_frames.finish();
    const BadInput& bad = GetParam();
    const auto result = run(bad.app, bad.arguments, dir.path());
    EXPECT_EQ(result.exit_code, bad.usage_error ? 2 : 1);
    EXPECT_EQ(result.out, "");
    EXPECT_EQ(line_count(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(bad.message), std::string::npos) << result.err;
    EXPECT_EQ(test_support::read_text(dir / "existing.webp"), "precious");
    EXPECT_EQ(dir.entries(),
              (std::vector<std::string>{"a-fifo", "a-file", "a-link.webp", "existing.webp", "two-frames.webp"}));
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, ExporterRejects,
    ::testing::Values(
        BadInput{"UnknownOption",
                 kStillCube,
                 {"--colour", "red", "existing.webp"},
                 "were not expected: existing.webp --colour"},
        BadInput{"ZeroWidth",
                 kStillCube,
                 {"--width", "0", "existing.webp"},
                 "--width: 0 is out of range (expected 1..16383)"},
        BadInput{"NegativeHeight", kStillCube, {"--height", "-3", "existing.webp"}, "--height: -3 is out of range"},
        BadInput{
            "AbsurdWidth", kStillUnitCube, {"--width", "100000", "existing.webp"}, "--width: 100000 is out of range"},
        BadInput{"HeightBeyondInt",
                 kAnimatedCube,
                 {"--height", "999999999999", "existing.webp"},
                 "--height: 999999999999 is out of range"},
        BadInput{
            "WidthNotANumber", kStillCube, {"--width", "abc", "existing.webp"}, "--width: 'abc' is not an integer"},
        BadInput{"HexadecimalFrames",
                 kAnimatedCube,
                 {"--frames", "0x10", "existing.webp"},
                 "--frames: '0x10' is not an integer"},
        BadInput{"FractionalFps", kAnimatedCube, {"--fps", "2.5", "existing.webp"}, "--fps: '2.5' is not an integer"},
        BadInput{"ZeroFrames", kAnimatedCube, {"--frames", "0", "existing.webp"}, "--frames: 0 is out of range"},
        BadInput{"FpsBrowsersWouldSlowDown",
                 kAnimatedCube,
                 {"--fps", "96", "existing.webp"},
                 "--fps: 96 is out of range (expected 1..95)"},
        BadInput{"UnknownEffort",
                 kAnimatedCube,
                 {"--effort", "turbo", "existing.webp"},
                 "--effort: 'turbo' is not one of fast, default, max"},
        BadInput{"EffortByNumber",
                 kAnimatedCube,
                 {"--effort", "0", "existing.webp"},
                 "--effort: '0' is not one of fast, default, max"},
        BadInput{"UnknownStyle",
                 kStillCube,
                 {"--style", "wire", "existing.webp"},
                 "--style: 'wire' is not one of filled, wireframe, culled-wireframe"},
        BadInput{
            "StyleByNumber", kAnimatedCube, {"--style", "2", "existing.webp"}, "--style: '2' is not one of filled"},
        BadInput{"UnknownScene",
                 test_support::kStillScene,
                 {"--scene", "teapot", "existing.webp"},
                 "--scene: 'teapot' is not one of lit-cube, dodecahedron, orbit"},
        BadInput{"SceneFramesBeyondTheLimit",
                 test_support::kAnimatedScene,
                 {"--frames", "10001", "existing.webp"},
                 "--frames: 10001 is out of range (expected 0..10000)"},
        BadInput{"SceneSizeNotANumber",
                 test_support::kAnimatedScene,
                 {"--width", "8k", "existing.webp"},
                 "--width: '8k' is not an integer"},
        BadInput{"StraightAngleOfView",
                 test_support::kStillScene,
                 {"--perspective", "180", "existing.webp"},
                 "--perspective: 180 is out of range (expected 0..179)"},
        BadInput{"NegativeAngleOfView",
                 test_support::kAnimatedScene,
                 {"--perspective", "-5", "existing.webp"},
                 "--perspective: -5 is out of range (expected 0..179)"},
        BadInput{"SceneOutputIsADirectory", test_support::kStillScene, {"."}, "cannot write '.'", false},
        BadInput{"OutputTwice", kStillCube, {"-o", "a.webp", "existing.webp"}, "excludes"},
        BadInput{"MissingDirectory", kStillCube, {"missing/out.webp"}, "directory 'missing' does not exist", false},
        BadInput{"ParentIsAFile", kAnimatedCube, {"a-file/out.webp"}, "'a-file' is not a directory", false},
        BadInput{"OutputIsADirectory", kStillUnitCube, {"."}, "cannot write '.'", false},
        BadInput{
            "UnwritablePlace", kAnimatedCube, {"/proc/raster-cannot-write-here.webp"}, "cannot write '/proc/", false},
        BadInput{"OutputIsAFifo", kAnimatedCube, {"a-fifo"}, "cannot write 'a-fifo': it is a FIFO", false},
        BadInput{"OutputIsASymbolicLink",
                 kStillCube,
                 {"a-link.webp"},
                 "cannot write 'a-link.webp': it is a symbolic link",
                 false},
        BadInput{"FrameBeyondTheAnimation",
                 kWebpFrame,
                 {"two-frames.webp", "2", "existing.webp"},
                 "has 2 frame(s), numbered 0..1",
                 false},
        BadInput{"FrameOfAFileThatIsNotWebp",
                 kWebpFrame,
                 {"a-file", "0", "existing.webp"},
                 "'a-file' is empty, not a WebP file",
                 false}),
    [](const ::testing::TestParamInfo<BadInput>& param) { return param.param.case_name; });
