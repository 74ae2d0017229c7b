// The exporters as a user meets them: help, version, quiet and progress, stdout, safe files.
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>
#include <raster/version.hpp>

#include "support/file_events.hpp"
#include "support/scratch.hpp"

#include <csignal>
#include <sstream>
#include <gtest/gtest.h>
#include <sys/stat.h>

using raster::Framebuffer;
using test_support::kAnimatedCube;
using test_support::kStillCube;
using test_support::kStillUnitCube;
using test_support::kWebpFrame;
using test_support::run;
using test_support::ScratchDir;

namespace {

const std::vector<std::string> kApps{
    kStillCube, kAnimatedCube, kStillUnitCube, kWebpFrame, test_support::kStillScene, test_support::kAnimatedScene};

std::string name_of(const std::string& program) { return std::filesystem::path(program).filename().string(); }

// Waits until the started exporter has made and removed its probe, the temporary file that shows
// the directory takes the output before any frame is drawn; false if it ended or did otherwise.
bool probed(test_support::DirectoryEvents& events, int pid) {
    test_support::DirectoryEvents::Event made, gone;
    return events.next(pid, made) && made.created && events.next(pid, gone) && !gone.created && gone.name == made.name;
}

Framebuffer still_cube() {
    Framebuffer image(raster::kSceneWidth, raster::kSceneHeight);
    raster::render_still_cube(image, raster::CubeStyle::filled);
    return image;
}

}  // namespace

TEST(Cli, HelpFitsEightyColumnsWithoutTypeNoise) {
    const ScratchDir dir;
    for (const std::string& app : kApps) {
        const auto result = run(app, {"--help"}, dir.path());
        EXPECT_EQ(result.exit_code, 0) << app;
        std::istringstream lines(result.out);
        std::string line;
        int count = 0;
        while (std::getline(lines, line)) {
            ++count;
            EXPECT_LE(line.size(), 80U) << name_of(app) << ": " << line;
            for (const char* noise : {"INT", "TEXT", " in [", "ENUM", "UINT"}) {
                EXPECT_EQ(line.find(noise), std::string::npos) << name_of(app) << ": " << line;
            }
        }
        EXPECT_GT(count, 10) << app;
        for (const char* option : {"--quiet", "--progress", "--output", "--follow-symlinks", "--version"}) {
            EXPECT_NE(result.out.find(option), std::string::npos) << name_of(app) << " lacks " << option;
        }
    }
    EXPECT_NE(run(kAnimatedCube, {"--help"}, dir.path()).out.find("frames of 10 ms or less"), std::string::npos);
}

TEST(Cli, VersionNamesTheProgram) {
    const ScratchDir dir;
    for (const std::string& app : kApps) {
        const auto result = run(app, {"--version"}, dir.path());
        EXPECT_EQ(result.exit_code, 0);
        EXPECT_EQ(result.out, name_of(app) + " " + raster::kVersion + " (raster)\n");
    }
}

TEST(Cli, OutputOptionIsTheSameAsThePositional) {
    const ScratchDir dir;
    const auto result = run(kStillCube, {"-o", "named.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(raster::read_webp(dir / "named.webp").frames.at(0).image, still_cube());
    EXPECT_EQ(run(kStillCube, {"--output", "long.webp"}, dir.path()).exit_code, 0);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"long.webp", "named.webp"}));
}

TEST(Cli, DashWritesTheImageToStandardOutputAndTheReportToStandardError) {
    const ScratchDir dir;
    const auto result = run(kStillCube, {"-"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err.rfind("Wrote standard output: 800x600 still, ", 0), 0U) << result.err;
    test_support::write_text(dir / "piped.webp", result.out);
    EXPECT_EQ(raster::read_webp(dir / "piped.webp").frames.at(0).image, still_cube());
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"piped.webp"}) << "nothing named '-' appears";
}

TEST(Cli, QuietPrintsNothingOnSuccess) {
    const ScratchDir dir;
    for (const auto& arguments : {std::vector<std::string>{"--quiet", "q.webp"}, {"-q", "-"}}) {
        const auto result = run(kStillUnitCube, arguments, dir.path());
        EXPECT_EQ(result.exit_code, 0);
        EXPECT_EQ(result.err, "");
        if (arguments.back() != "-") {
            EXPECT_EQ(result.out, "");
        }
    }
}

TEST(Cli, APngNameWritesPngAndAnOddNameWarns) {
    const ScratchDir dir;
    auto result = run(kStillCube, {"cube.img"}, dir.path());
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_EQ(result.err, "still-cube: warning: 'cube.img' does not end in .webp, but it will hold WebP data\n");
    EXPECT_EQ(raster::read_webp(dir / "cube.img").frames.at(0).image, still_cube());
    result = run(kStillCube, {"cube.PNG"}, dir.path());
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_EQ(result.err, "");
    EXPECT_EQ(raster::decode_png(test_support::read_bytes(dir / "cube.PNG"), 1 << 20).image, still_cube());
}

TEST(Cli, ProgressCountsFramesThenAssemblyWhenAsked) {
    const ScratchDir dir;
    const auto result =
        run(kAnimatedCube, {"--progress", "--frames", "20", "--width", "40", "--height", "30", "p.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_NE(result.err.find("animated-cube: frame 2/20\n"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("animated-cube: frame 20/20\n"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("animated-cube: assembling the animation\n"), std::string::npos) << result.err;
    EXPECT_EQ(run(kAnimatedCube, {"--frames", "20", "p.webp"}, dir.path()).err, "") << "off when stderr is a file";
}

TEST(Cli, ATerminalSeesProgressInPlaceAndNoImageBytes) {
    const ScratchDir dir;
    const auto shown = test_support::run_on_terminal(
        kAnimatedCube, {"--frames", "5", "--width", "40", "--height", "30", "t.webp"}, dir.path());
    EXPECT_EQ(shown.exit_code, 0) << shown.out;
    EXPECT_NE(shown.out.find("\r\033[Kanimated-cube: frame 5/5"), std::string::npos) << shown.out;
    EXPECT_NE(shown.out.find("Wrote t.webp: 40x30, 5 frames, 100 ms"), std::string::npos) << shown.out;
    const auto refused = test_support::run_on_terminal(kStillCube, {"-"}, dir.path());
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_NE(refused.out.find("standard output is a terminal"), std::string::npos) << refused.out;
}

TEST(Cli, FollowSymlinksWritesThroughALink) {
    const ScratchDir dir;
    test_support::write_text(dir / "real.webp", "old");
    std::filesystem::create_symlink("real.webp", dir / "link.webp");
    const auto result = run(kStillCube, {"--follow-symlinks", "link.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.webp"));
    EXPECT_EQ(raster::read_webp(dir / "real.webp").frames.at(0).image, still_cube());
}

TEST(Cli, NewFilesRespectTheUmaskAndReplacedFilesKeepTheirMode) {
    const ScratchDir dir;
    const mode_t previous = ::umask(077);
    EXPECT_EQ(run(kStillUnitCube, {"private.webp"}, dir.path()).exit_code, 0);
    ::umask(previous);
    struct stat status {};
    ASSERT_EQ(::stat((dir / "private.webp").c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 0777, 0600U);
    ASSERT_EQ(::chmod((dir / "private.webp").c_str(), 0640), 0);
    EXPECT_EQ(run(kStillCube, {"private.webp"}, dir.path()).exit_code, 0);
    ASSERT_EQ(::stat((dir / "private.webp").c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 0777, 0640U);
}

TEST(Cli, NamesOfTwoHundredFiftyFiveBytesWork) {
    const ScratchDir dir;
    const std::string longest = std::string(250, 'c') + ".webp";
    const auto result = run(kStillUnitCube, {longest}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(dir.entries(), std::vector<std::string>{longest});
}

TEST(Cli, InterruptsLeaveNoFileBehindAndTheExistingOutputUnchanged) {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        SCOPED_TRACE(strsignal(signal));
        const ScratchDir dir;
        test_support::write_text(dir / "existing.webp", "precious");
        test_support::DirectoryEvents events(dir.path());
        // Once probed, the exporter draws ten thousand frames before it writes: the signal lands mid-drawing.
        const int pid = test_support::start(kAnimatedCube, {"--frames", "10000", "existing.webp"}, dir.path());
        EXPECT_TRUE(probed(events, pid));
        ::kill(pid, signal);
        EXPECT_EQ(test_support::wait_for_signal(pid), signal);
        EXPECT_EQ(dir.entries(), std::vector<std::string>{"existing.webp"});
        EXPECT_EQ(test_support::read_text(dir / "existing.webp"), "precious");
        const int fresh = test_support::start(kAnimatedCube, {"--frames", "10000", "new.webp"}, dir.path());
        EXPECT_TRUE(probed(events, fresh));
        ::kill(fresh, signal);
        EXPECT_EQ(test_support::wait_for_signal(fresh), signal);
        EXPECT_EQ(dir.entries(), std::vector<std::string>{"existing.webp"});
    }
}

TEST(Cli, AnInterruptWhileTheOutputIsWrittenWaitsForTheWholeFileThenEndsTheProgram) {
    constexpr int kFrames = 4;
    constexpr int kAttempts = 10;
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        SCOPED_TRACE(strsignal(signal));
        bool caught = false;
        // The writer is stopped as its temporary file appears; a write that ended before it stopped is tried again.
        for (int attempt = 0; attempt < kAttempts && !caught; ++attempt) {
            const ScratchDir dir;
            test_support::write_text(dir / "existing.webp", "precious");
            test_support::DirectoryEvents events(dir.path());
            const int pid =
                test_support::start(kAnimatedCube, {"--frames", std::to_string(kFrames), "existing.webp"}, dir.path());
            test_support::DirectoryEvents::Event temporary;
            ASSERT_TRUE(probed(events, pid) && events.next(pid, temporary) && temporary.created);
            caught = test_support::signal_while_present(pid, dir / temporary.name, signal);
            EXPECT_EQ(test_support::wait_for_signal(pid), caught ? signal : 0);
            EXPECT_EQ(dir.entries(), std::vector<std::string>{"existing.webp"}) << "no temporary file is left";
            EXPECT_EQ(raster::read_webp(dir / "existing.webp").frames.size(), std::size_t{kFrames})
                << "the new file is whole";
        }
        if (!caught) GTEST_SKIP() << "in " << kAttempts << " tries every write ended before its writer was stopped";
    }
}

TEST(Cli, LeadingZerosAreDecimalNotOctal) {
    const ScratchDir dir;
    const auto result = run(kStillUnitCube, {"--width", "010", "--height", "08", "z.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedWebp decoded = raster::read_webp(dir / "z.webp");
    EXPECT_EQ(decoded.width, 10);
    EXPECT_EQ(decoded.height, 8);
}

TEST(Cli, ChoicesIgnoreCase) {
    const ScratchDir dir;
    EXPECT_EQ(run(kStillCube, {"--style", "WireFrame", "--effort", "FAST", "w.webp"}, dir.path()).exit_code, 0);
    Framebuffer expected(raster::kSceneWidth, raster::kSceneHeight);
    raster::render_still_cube(expected, raster::CubeStyle::wireframe);
    EXPECT_EQ(raster::read_webp(dir / "w.webp").frames.at(0).image, expected);
}
