#include <raster/io/frame_range.hpp>

#include <optional>
#include <gtest/gtest.h>

using raster::frame_range_from_text;
using raster::FrameRange;

TEST(FrameRangeFromText, ReadsDotsOrColonBetweenTwoDecimalFrames) {
    EXPECT_EQ(frame_range_from_text("3..7"), (FrameRange{3, 7, 0, 0}));
    EXPECT_EQ(frame_range_from_text("3:7"), (FrameRange{3, 7, 0, 0}));
    EXPECT_EQ(frame_range_from_text("0..0"), (FrameRange{0, 0, 0, 0}));
    EXPECT_EQ(frame_range_from_text("007..012"), (FrameRange{7, 12, 0, 0}));  // decimal, not octal
    EXPECT_EQ(frame_range_from_text("0..999999999"), (FrameRange{0, 999999999, 0, 0}));
}

TEST(FrameRangeFromText, LeavesTheClipsLengthAndSpacingToTheCaller) {
    const std::optional<FrameRange> range = frame_range_from_text("2..5");
    ASSERT_TRUE(range);
    EXPECT_EQ(range->total, 0);
    EXPECT_EQ(range->spacing_ms, 0);
    EXPECT_EQ(range->count(), 4);
}

TEST(FrameRangeFromText, RefusesABackwardRange) {
    EXPECT_EQ(frame_range_from_text("7..3"), std::nullopt);
    EXPECT_EQ(frame_range_from_text("1:0"), std::nullopt);
}

TEST(FrameRangeFromText, RefusesAnythingButTwoPlainDecimalNumbers) {
    for (const char* text : {"", "5", "..", ":", "..5", "5..", "-1..3", "+1..3", "1..+3", " 1..3", "1..3 ", "1...3",
                             "1..3..5", "1:3:5", "a..b", "0x1..2", "1.5..3", "1234567890..1234567891"}) {
        EXPECT_EQ(frame_range_from_text(text), std::nullopt) << text;
    }
}
