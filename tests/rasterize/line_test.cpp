#include <raster/rasterize/line.hpp>

#include "support/picture.hpp"

#include <cmath>
#include <random>
#include <gtest/gtest.h>

using raster::draw_line;
using raster::Framebuffer;
using test_support::looks_like;

namespace {

constexpr raster::Rgb kWhite{255, 255, 255};

Framebuffer line_on_10x5(glm::ivec2 from, glm::ivec2 to) {
    Framebuffer image(10, 5);
    draw_line(image, from, to, kWhite);
    return image;
}

// The diary's DDA taken literally: every one of the N + 1 samples, rounded, halves up.
void draw_every_sample(Framebuffer& image, glm::ivec2 from, glm::ivec2 to) {
    const int dx = to.x - from.x;
    const int dy = to.y - from.y;
    const int steps = std::max(std::abs(dx), std::abs(dy));
    for (int i = 0; i <= steps; ++i) {
        const double x = from.x + (steps == 0 ? 0.0 : static_cast<double>(dx) * i / steps);
        const double y = from.y + (steps == 0 ? 0.0 : static_cast<double>(dy) * i / steps);
        image.set_pixel(static_cast<int>(std::floor(x + 0.5)), static_cast<int>(std::floor(y + 0.5)), kWhite);
    }
}

}  // namespace

TEST(DrawLine, HorizontalIncludesBothEndpoints) {
    EXPECT_TRUE(looks_like(line_on_10x5({1, 2}, {7, 2}),
                           {"..........", "..........", ".+++++++..", "..........", ".........."}));
}

TEST(DrawLine, VerticalIncludesBothEndpoints) {
    EXPECT_TRUE(looks_like(line_on_10x5({3, 0}, {3, 4}),
                           {"...+......", "...+......", "...+......", "...+......", "...+......"}));
}

TEST(DrawLine, FortyFiveDegreesStepsOneDiagonalPixelAtATime) {
    EXPECT_TRUE(looks_like(line_on_10x5({1, 0}, {4, 3}),
                           {".+........", "..+.......", "...+......", "....+.....", ".........."}));
}

TEST(DrawLine, ShallowLineHasOnePixelPerColumn) {
    EXPECT_TRUE(looks_like(line_on_10x5({0, 0}, {9, 3}),
                           {"++........", "..+++.....", ".....+++..", "........++", ".........."}));
}

TEST(DrawLine, SteepLineHasOnePixelPerRowAndRoundsHalvesUp) {
    EXPECT_TRUE(looks_like(line_on_10x5({1, 0}, {3, 4}),
                           {".+........", "..+.......", "..+.......", "...+......", "...+......"}));
}

TEST(DrawLine, ReversedEndpointsDrawTheSamePixels) {
    for (const auto& [a, b] :
         {std::pair<glm::ivec2, glm::ivec2>{{1, 0}, {3, 4}}, {{0, 0}, {9, 3}}, {{2, 4}, {9, 0}}, {{0, 1}, {7, 2}}}) {
        EXPECT_EQ(line_on_10x5(a, b), line_on_10x5(b, a));
    }
}

TEST(DrawLine, ZeroLengthSegmentIsOnePixel) {
    EXPECT_TRUE(looks_like(line_on_10x5({4, 2}, {4, 2}),
                           {"..........", "..........", "....+.....", "..........", ".........."}));
}

TEST(DrawLine, ClipsAtTheLeftBorder) {
    Framebuffer image(10, 5);
    EXPECT_EQ(draw_line(image, {-3, 1}, {4, 1}, kWhite), 5);
    EXPECT_TRUE(looks_like(image, {"..........", "+++++.....", "..........", "..........", ".........."}));
}

TEST(DrawLine, ClipsAtTheRightBorder) {
    Framebuffer image(10, 5);
    EXPECT_EQ(draw_line(image, {6, 3}, {14, 3}, kWhite), 4);
    EXPECT_TRUE(looks_like(image, {"..........", "..........", "..........", "......++++", ".........."}));
}

TEST(DrawLine, ClipsAtTheTopBorder) {
    Framebuffer image(10, 5);
    EXPECT_EQ(draw_line(image, {2, -4}, {2, 2}, kWhite), 3);
    EXPECT_TRUE(looks_like(image, {"..+.......", "..+.......", "..+.......", "..........", ".........."}));
}

TEST(DrawLine, ClipsAtTheBottomBorder) {
    Framebuffer image(10, 5);
    EXPECT_EQ(draw_line(image, {8, 3}, {8, 9}, kWhite), 2);
    EXPECT_TRUE(looks_like(image, {"..........", "..........", "..........", "........+.", "........+."}));
}

TEST(DrawLine, ClipsThroughACorner) {
    Framebuffer image(10, 5);
    EXPECT_EQ(draw_line(image, {-2, -2}, {3, 3}, kWhite), 4);
    EXPECT_TRUE(looks_like(image, {"+.........", ".+........", "..+.......", "...+......", ".........."}));
}

TEST(DrawLine, SegmentThatMissesTheBufferWalksNothing) {
    Framebuffer image(10, 5);
    EXPECT_EQ(draw_line(image, {-50, -3}, {60, -1}, kWhite), 0);
    EXPECT_EQ(draw_line(image, {12, 0}, {40, 4}, kWhite), 0);
    EXPECT_EQ(draw_line(image, {-7, -7}, {-7, -7}, kWhite), 0);
    EXPECT_EQ(image, Framebuffer(10, 5));
}

TEST(DrawLine, HugeHorizontalSegmentWalksOnlyItsVisiblePixels) {
    Framebuffer image(10, 10);
    EXPECT_EQ(draw_line(image, {-1'000'000'000, 5}, {1'000'000'000, 5}, kWhite), 10);
    Framebuffer expected(10, 10);
    draw_line(expected, {0, 5}, {9, 5}, kWhite);
    EXPECT_EQ(image, expected);
}

TEST(DrawLine, HugeVerticalAndDiagonalSegmentsWalkOnlyTheirVisiblePixels) {
    Framebuffer vertical(10, 10);
    EXPECT_EQ(draw_line(vertical, {5, 1'000'000'000}, {5, -1'000'000'000}, kWhite), 10);
    Framebuffer diagonal(10, 10);
    EXPECT_EQ(draw_line(diagonal, {-1'000'000'000, -1'000'000'000}, {1'000'000'000, 1'000'000'000}, kWhite), 10);
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(vertical.pixel(5, i), kWhite);
        EXPECT_EQ(diagonal.pixel(i, i), kWhite);
    }
}

TEST(DrawLine, ExtremeEndpointsDoNotOverflow) {
    Framebuffer image(10, 10);
    const int lo = -2147483647 - 1;
    const int hi = 2147483647;
    draw_line(image, {lo, lo}, {hi, hi}, kWhite);
    draw_line(image, {lo, 4}, {hi, 4}, kWhite);
    draw_line(image, {hi, lo}, {lo, hi}, kWhite);
    for (int x = 0; x < 10; ++x) EXPECT_EQ(image.pixel(x, 4), kWhite);
}

TEST(DrawLine, WalkingOnlyVisibleSamplesMatchesWalkingEverySample) {
    std::mt19937 random(20261121);
    std::uniform_int_distribution<int> coordinate(-2000, 2000);
    std::uniform_int_distribution<int> near(-30, 50);
    for (int round = 0; round < 400; ++round) {
        const bool long_segment = round % 2 == 0;
        auto pick = [&] { return long_segment ? coordinate(random) : near(random); };
        const glm::ivec2 from{pick(), pick()};
        const glm::ivec2 to{pick(), pick()};
        Framebuffer bounded(23, 17);
        Framebuffer full(23, 17);
        draw_line(bounded, from, to, kWhite);
        draw_every_sample(full, from, to);
        ASSERT_EQ(bounded, full) << "segment (" << from.x << ", " << from.y << ") -> (" << to.x << ", " << to.y << ")\n"
                                 << test_support::to_ascii_art(bounded) << "vs every sample\n"
                                 << test_support::to_ascii_art(full);
    }
}
