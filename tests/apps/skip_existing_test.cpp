// --skip-existing keeps only what a run could have written: a regular file, not empty, that
// decodes; a link, a directory, an empty or damaged file under the name is drawn again or refused.
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using test_support::kAnimatedCube;
using test_support::kRender;
using test_support::read_bytes;
using test_support::run;
using test_support::ScratchDir;

namespace {

std::vector<std::string> with(std::vector<std::string> arguments, const std::vector<std::string>& more) {
    arguments.insert(arguments.end(), more.begin(), more.end());
    return arguments;
}

const std::vector<std::string> kPart{"--width",  "64", "--height",      "48",   "--effort",       "fast",
                                     "--frames", "10", "--frame-range", "2..5", "--skip-existing"};

}  // namespace

TEST(SkipExisting, ALinkADirectoryOrAnEmptyFileNamedLikeTheAnimationIsNotTakenAsFinished) {
    const ScratchDir dir;
    ASSERT_EQ(run(kAnimatedCube, with(kPart, {"--quiet", "real.webp"}), dir.path()).exit_code, 0);
    std::filesystem::create_symlink("real.webp", dir / "linked.webp");
    const auto linked = run(kAnimatedCube, with(kPart, {"linked.webp"}), dir.path());
    EXPECT_EQ(linked.exit_code, 1) << linked.out;  // drawn, then refused: outputs are not written through links
    EXPECT_EQ(linked.out, "");
    std::filesystem::create_directory(dir / "folder.webp");
    const auto folder = run(kAnimatedCube, with(kPart, {"folder.webp"}), dir.path());
    EXPECT_EQ(folder.exit_code, 1);
    EXPECT_EQ(folder.out, "");
    test_support::write_text(dir / "empty.webp", "");
    const auto empty = run(kAnimatedCube, with(kPart, {"empty.webp"}), dir.path());
    ASSERT_EQ(empty.exit_code, 0) << empty.err;
    EXPECT_EQ(empty.out.rfind("Wrote empty.webp", 0), 0U) << empty.out;
    EXPECT_EQ(raster::read_webp(dir / "empty.webp").frames.size(), 4U);
}

TEST(SkipExisting, OnlyNumberedFramesThatDecodeAsPngAreKept) {
    const ScratchDir dir;
    const std::vector<std::string> frames{"--width", "32", "--height", "24", "--frames", "6", "--frames-dir", "f"};
    ASSERT_EQ(run(kAnimatedCube, with(frames, {"--quiet"}), dir.path()).exit_code, 0);
    std::vector<std::vector<std::uint8_t>> drawn;
    for (int i = 0; i < 6; ++i) drawn.push_back(read_bytes(dir / "f" / ("000" + std::to_string(i) + ".png")));
    test_support::write_text(dir / "f" / "0001.png", "");
    test_support::write_text(dir / "f" / "0002.png", "not a picture");
    std::filesystem::resize_file(dir / "f" / "0003.png", drawn[3].size() / 2);  // cut short
    const auto refill = run(kAnimatedCube, with(frames, {"--skip-existing"}), dir.path());
    ASSERT_EQ(refill.exit_code, 0) << refill.err;
    EXPECT_NE(refill.out.find(": 3 PNG frames of 32x24"), std::string::npos) << refill.out;
    EXPECT_NE(refill.out.find("3 already there kept"), std::string::npos) << refill.out;
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(read_bytes(dir / "f" / ("000" + std::to_string(i) + ".png")), drawn[static_cast<std::size_t>(i)])
            << i;
    // A link or a directory under a frame's name is not a frame: it is in the way, and said so.
    std::filesystem::remove(dir / "f" / "0004.png");
    std::filesystem::create_symlink("0000.png", dir / "f" / "0004.png");
    const auto linked = run(kAnimatedCube, with(frames, {"--skip-existing"}), dir.path());
    EXPECT_EQ(linked.exit_code, 1);
    EXPECT_NE(linked.err.find("0004.png"), std::string::npos) << linked.err;
    std::filesystem::remove(dir / "f" / "0004.png");
    std::filesystem::create_directory(dir / "f" / "0004.png");
    const auto folder = run(kAnimatedCube, with(frames, {"--skip-existing"}), dir.path());
    EXPECT_EQ(folder.exit_code, 1);
    EXPECT_NE(folder.err.find("0004.png"), std::string::npos) << folder.err;
}

TEST(SkipExisting, ABatchDrawsAgainPicturesThatAreEmptyDamagedOrNotWebp) {
    const ScratchDir dir;
    const std::string crate = test_support::write_crate_on_floor(dir.path()).string();
    for (const char* copy : {"b.obj", "c.obj", "d.obj"}) std::filesystem::copy_file(crate, dir / copy);
    const std::vector<std::string> batch{"--width", "32",  "--height", "24",    "--output-dir",
                                         "t",       crate, "b.obj",    "c.obj", "d.obj"};
    ASSERT_EQ(run(kRender, with(batch, {"--quiet"}), dir.path()).exit_code, 0);
    const std::vector<std::uint8_t> picture = read_bytes(dir / "t" / "b.webp");
    test_support::write_text(dir / "t" / "b.webp", "");
    test_support::write_text(dir / "t" / "c.webp", std::string("RIFF\x10\0\0\0WEBPVP8L damaged", 24));
    std::filesystem::remove(dir / "t" / "d.webp");
    std::filesystem::create_directory(dir / "t" / "d.webp");
    const auto again = run(kRender, with(batch, {"--skip-existing"}), dir.path());
    EXPECT_EQ(again.exit_code, 1);
    EXPECT_NE(again.err.find("wrote 2 of 3 models into t in "), std::string::npos) << again.err;
    EXPECT_NE(again.err.find(", 1 already there kept; 1 failed"), std::string::npos) << again.err;
    EXPECT_EQ(read_bytes(dir / "t" / "b.webp"), picture);
    EXPECT_EQ(read_bytes(dir / "t" / "c.webp"), picture);
    EXPECT_NE(again.err.find("render: d.obj: cannot write 't/d.webp': it is a directory\n"), std::string::npos)
        << again.err;
}
