#include <raster/image/framebuffer.hpp>

#include "support/picture.hpp"

#include <stdexcept>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::Rgb;
using test_support::looks_like;

namespace {
constexpr Rgb kWhite{255, 255, 255};
}

TEST(Framebuffer, IsBlackWhenCreated) {
    const Framebuffer image(4, 3);
    EXPECT_TRUE(looks_like(image, {"....", "....", "...."}));
    EXPECT_EQ(image.bytes().size(), 4U * 3U * 3U);
}

TEST(Framebuffer, SetPixelWritesOnePixelAtColumnAndRow) {
    Framebuffer image(4, 3);
    image.set_pixel(3, 1, kWhite);
    EXPECT_TRUE(looks_like(image, {"....", "...+", "...."}));
}

TEST(Framebuffer, StoresRowMajorRgbBytes) {
    Framebuffer image(2, 2);
    image.set_pixel(1, 0, {1, 2, 3});
    image.set_pixel(0, 1, {4, 5, 6});
    const std::vector<std::uint8_t> expected{0, 0, 0, 1, 2, 3, 4, 5, 6, 0, 0, 0};
    EXPECT_EQ(std::vector<std::uint8_t>(image.bytes().begin(), image.bytes().end()), expected);
}

TEST(Framebuffer, SkipsWritesOutsideIncludingNegativeCoordinatesWithoutWrapping) {
    Framebuffer image(4, 3);
    for (const auto& [x, y] :
         {std::pair{-1, 0}, {0, -1}, {4, 0}, {0, 3}, {-1, -1}, {4, 3}, {-2147483647 - 1, 1}, {1, 2147483647}}) {
        image.set_pixel(x, y, kWhite);
    }
    EXPECT_TRUE(looks_like(image, {"....", "....", "...."}));
}

TEST(Framebuffer, FillRowTakesSpansAnywhereInThePlane) {
    Framebuffer image(4, 3);
    constexpr int kMin = -2147483647 - 1;
    constexpr int kMax = 2147483647;
    for (const auto& [begin, end] : {std::pair{-10, -5},
                                     {kMin, kMin},
                                     {kMin, -1},
                                     {4, 9},
                                     {kMax, kMin},
                                     {3, 1},
                                     {kMax, kMax},
                                     {-20, -19},
                                     {2, 2}}) {
        for (const int y : {0, 1, 2}) image.fill_row(y, begin, end, kWhite);
    }
    EXPECT_TRUE(looks_like(image, {"....", "....", "...."})) << "spans off the buffer or empty paint nothing";
    image.fill_row(kMin, kMin, kMax, kWhite);
    image.fill_row(kMax, kMin, kMax, kWhite);
    image.fill_row(0, kMin, 2, kWhite);
    image.fill_row(1, kMin, kMax, kWhite);
    image.fill_row(2, 3, kMax, kWhite);
    EXPECT_TRUE(looks_like(image, {"++..", "++++", "...+"}));
}

TEST(Framebuffer, ClearPaintsEveryPixel) {
    Framebuffer image(3, 2);
    image.clear({9, 8, 7});
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) EXPECT_EQ(image.pixel(x, y), (Rgb{9, 8, 7}));
    }
}

TEST(Framebuffer, ReadingOutsideThrows) {
    const Framebuffer image(2, 2);
    EXPECT_THROW((void)image.pixel(2, 0), std::out_of_range);
    EXPECT_THROW((void)image.pixel(0, -1), std::out_of_range);
}

TEST(Framebuffer, RejectsEmptyNegativeAndOversizedDimensions) {
    EXPECT_THROW(Framebuffer(0, 5), std::invalid_argument);
    EXPECT_THROW(Framebuffer(5, -1), std::invalid_argument);
    EXPECT_THROW(Framebuffer(raster::kMaxImageSide + 1, 1), std::invalid_argument);
    EXPECT_NO_THROW(Framebuffer(raster::kMaxImageSide, 1));
}

TEST(Framebuffer, AdoptsBytesOnlyOfTheRightSize) {
    EXPECT_THROW(Framebuffer(2, 2, std::vector<std::uint8_t>(11)), std::invalid_argument);
    const Framebuffer image(1, 1, {7, 8, 9});
    EXPECT_EQ(image.pixel(0, 0), (Rgb{7, 8, 9}));
}
