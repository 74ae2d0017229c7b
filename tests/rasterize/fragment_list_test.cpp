// The fragments of a strip are bounded: one past its share is a clear error, never a crash
// (doc/conventions.md#transparency).
#include "rasterize/fragment_list.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include <gtest/gtest.h>

TEST(FragmentList, OnePastItsCapIsAClearError) {
    raster::detail::FragmentList list(2);
    list.add(1.0F, 0.5F, 0, 1).colour[0] = 7;
    list.add(2.0F, 0.5F, 1, 1);
    EXPECT_EQ(list.size(), 2U);
    EXPECT_EQ(list[0].colour[0], 7);  // kept where it was written
    try {
        list.add(3.0F, 0.5F, 2, 1);
        FAIL() << "a third fragment was kept";
    } catch (const std::length_error& error) {
        EXPECT_NE(std::string(error.what()).find("1024 MiB of fragments"), std::string::npos) << error.what();
    }
    EXPECT_EQ(list.size(), 2U);
}

TEST(FragmentList, CountsEachPixelsFragmentsAsTheyComeAndForgetsThemWhenCleared) {
    raster::detail::FragmentList list;
    list.clear(8, 100, 3);  // pixels 100..102 of the frame
    list.add(1.0F, 0.5F, 101, 1);
    list.add(2.0F, 0.5F, 101, 1);
    list.add(3.0F, 0.5F, 102, 1);
    EXPECT_EQ(list.starts, (std::vector<std::uint32_t>{0, 0, 2, 1}));
    list.clear(8, 0, 2);
    EXPECT_TRUE(list.empty());
    EXPECT_EQ(list.starts, (std::vector<std::uint32_t>{0, 0, 0}));
}
