#include <raster/io/frame_timing.hpp>

#include <cstdint>
#include <gtest/gtest.h>

using raster::frame_spacing_ms;
using raster::frames_length_ms;

TEST(FrameTiming, SpacingIsAThousandOverFpsRoundedToTheNearestMillisecond) {
    EXPECT_EQ(frame_spacing_ms(50), 20);
    EXPECT_EQ(frame_spacing_ms(1), 1000);
    EXPECT_EQ(frame_spacing_ms(30), 33);  // 33.3
    EXPECT_EQ(frame_spacing_ms(24), 42);  // 41.67
    EXPECT_EQ(frame_spacing_ms(16), 63);  // 62.5 rounds up
    EXPECT_EQ(frame_spacing_ms(95), 11);  // the fastest rate browsers play as asked
}

TEST(FrameTiming, FramesLastTheirCountTimesTheSpacing) {
    EXPECT_EQ(frames_length_ms(360, 20), 7200);
    EXPECT_EQ(frames_length_ms(1, 33), 33);
    EXPECT_EQ(frames_length_ms(0, 20), 0);
}

TEST(FrameTiming, ALongClipsLengthDoesNotOverflowAnInt) {
    EXPECT_EQ(frames_length_ms(2'000'000, 2'000), std::int64_t{4'000'000'000});
}
