// render --timings: a table of the job's stages on standard error, after the one-line report.
#include <raster/io/webp.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <sstream>
#include <string>
#include <vector>
#include <gtest/gtest.h>

using test_support::kRender;
using test_support::run;
using test_support::ScratchDir;

namespace {

// The lines of `text`.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Whether `lines` hold the table: its heading, then a row for every stage in order, numbers and a share each.
void expect_stage_table(const std::vector<std::string>& lines) {
    ASSERT_GE(lines.size(), 7U);
    EXPECT_EQ(lines[0], "stage      wall s    cpu s  one core");
    const char* const stages[] = {"read", "prepare", "draw", "resolve", "encode"};
    for (std::size_t i = 0; i < 5; ++i) {
        std::istringstream row(lines[i + 1]);
        std::string name, share;
        double wall = -1.0, processor = -1.0;
        row >> name >> wall >> processor >> share;
        EXPECT_EQ(name, stages[i]) << lines[i + 1];
        EXPECT_GE(wall, 0.0) << lines[i + 1];
        EXPECT_GE(processor, 0.0) << lines[i + 1];
        EXPECT_TRUE(share == "-" || share.back() == '%') << lines[i + 1];  // "-": a stage that took no time
    }
    EXPECT_EQ(lines[6].rfind("one core: ", 0), 0U) << lines[6];
}

}  // namespace

TEST(RenderTimings, AStillPrintsEveryStageAfterItsUnchangedReport) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    const auto timed =
        run(kRender, {"crate.obj", "--width", "64", "--height", "48", "--timings", "timed.webp"}, dir.path());
    ASSERT_EQ(timed.exit_code, 0) << timed.err;
    EXPECT_EQ(timed.out.rfind("Wrote timed.webp: 64x48 still, ", 0), 0U) << timed.out;
    EXPECT_NE(timed.out.find(", 14 triangles, "), std::string::npos) << timed.out;
    EXPECT_EQ(timed.out.find('\n'), timed.out.size() - 1) << timed.out;  // the report stays one line
    expect_stage_table(lines_of(timed.err));
    const auto plain = run(kRender, {"crate.obj", "--width", "64", "--height", "48", "plain.webp"}, dir.path());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(plain.err, "");
    EXPECT_EQ(raster::read_webp(dir / "timed.webp").frames.at(0).image,
              raster::read_webp(dir / "plain.webp").frames.at(0).image);
}

TEST(RenderTimings, ATurntableSumsItsFramesIntoTheSameTable) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    const auto result = run(kRender,
                            {"crate.obj", "--turntable", "3", "--width", "32", "--height", "24", "--effort", "fast",
                             "--timings", "--threads", "2", "spin.webp"},
                            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("Wrote spin.webp: 32x24, 3 frames, ", 0), 0U) << result.out;
    const std::vector<std::string> lines = lines_of(result.err);
    expect_stage_table(lines);
    EXPECT_NE(lines.back().find("of the 2 threads"), std::string::npos) << lines.back();
}

TEST(RenderTimings, ABatchIsRefusedInOneLine) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    const auto result = run(kRender, {"crate.obj", "--output-dir", "out", "--timings"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err,
              "render: --timings times the stages of one model's job; a batch (--output-dir) overlaps them, so time "
              "one model (see --help)\n");
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"checker.png", "crate.mtl", "crate.obj"}));  // no out/
}
