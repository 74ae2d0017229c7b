#include <raster/io/frame_files.hpp>

#include <cstdio>
#include <gtest/gtest.h>

using raster::frame_file_name;

TEST(FrameFileName, IsTheNumberInFourDigitsAsPrintfsPercent04d) {
    EXPECT_EQ(frame_file_name(0), "0000.png");
    EXPECT_EQ(frame_file_name(7), "0007.png");
    EXPECT_EQ(frame_file_name(1234), "1234.png");
    for (const int index : {0, 9, 10, 999, 9999, 10000, 123456}) {
        char expected[32];
        std::snprintf(expected, sizeof expected, "%04d.png", index);
        EXPECT_EQ(frame_file_name(index), expected) << index;
    }
}

TEST(FrameFileName, AClipOfUpTo10000FramesKeepsFourDigits) {
    EXPECT_EQ(frame_file_name(3, 1), "0003.png");
    EXPECT_EQ(frame_file_name(3, 10000), "0003.png");
    EXPECT_EQ(frame_file_name(9999, 10000), "9999.png");
}

TEST(FrameFileName, ALongerClipTakesAsManyDigitsAsItsLastFrameSoNamesSort) {
    EXPECT_EQ(frame_file_name(3, 10001), "00003.png");
    EXPECT_EQ(frame_file_name(10000, 10001), "10000.png");
    EXPECT_EQ(frame_file_name(42, 1'000'000), "000042.png");
}
