#include <raster/fill.hpp>

#include "support/picture.hpp"

#include <algorithm>
#include <gtest/gtest.h>

using raster::fill_quad;
using raster::Framebuffer;
using test_support::looks_like;
using Quad = std::array<glm::ivec2, 4>;

namespace {

constexpr raster::Rgb kWhite{255, 255, 255};

Framebuffer quad_on_10x5(const Quad& corners) {
    Framebuffer image(10, 5);
    fill_quad(image, corners, kWhite);
    return image;
}

Quad starting_at(Quad corners, std::size_t first) {
    std::rotate(corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(first), corners.end());
    return corners;
}

Quad reversed(Quad corners) {
    std::reverse(corners.begin(), corners.end());
    return corners;
}

}  // namespace

TEST(FillQuad, RectangleIncludesItsEdges) {
    EXPECT_TRUE(looks_like(quad_on_10x5({{{2, 1}, {7, 1}, {7, 3}, {2, 3}}}),
                           {"..........", "..++++++..", "..++++++..", "..++++++..", ".........."}));
}

TEST(FillQuad, SlantedQuadKeepsPixelCentresOnOrInsideEdges) {
    EXPECT_TRUE(looks_like(quad_on_10x5({{{2, 3}, {7, 3}, {8, 1}, {1, 1}}}),
                           {"..........", ".++++++++.", "..++++++..", "..++++++..", ".........."}));
}

TEST(FillQuad, DiamondFillsRowsSymmetrically) {
    EXPECT_TRUE(looks_like(quad_on_10x5({{{4, 0}, {8, 2}, {4, 4}, {0, 2}}}),
                           {"....+.....", "..+++++...", "+++++++++.", "..+++++...", "....+....."}));
}

TEST(FillQuad, EitherWindingAndEveryStartingCornerFillTheSamePixels) {
    const Quad slanted{{{2, 3}, {7, 3}, {8, 1}, {1, 1}}};
    const Framebuffer expected = quad_on_10x5(slanted);
    for (std::size_t first = 0; first < 4; ++first) {
        EXPECT_EQ(quad_on_10x5(starting_at(slanted, first)), expected) << "start " << first;
        EXPECT_EQ(quad_on_10x5(reversed(starting_at(slanted, first))), expected)
            << "reversed, start " << first;
    }
}

TEST(FillQuad, ClipsAtTheRightBorder) {
    EXPECT_TRUE(looks_like(quad_on_10x5({{{2, 1}, {14, 1}, {14, 3}, {2, 3}}}),
                           {"..........", "..++++++++", "..++++++++", "..++++++++", ".........."}));
}

TEST(FillQuad, ClipsAtTheTopLeftAndTestsOnlyVisiblePixels) {
    Framebuffer image(10, 5);
    EXPECT_EQ(fill_quad(image, {{{-5, -5}, {4, -5}, {4, 2}, {-5, 2}}}, kWhite), 15);
    EXPECT_TRUE(looks_like(image, {"+++++.....", "+++++.....", "+++++.....", "..........", ".........."}));
}

TEST(FillQuad, HugeQuadCostsOnlyTheBufferItCovers) {
    Framebuffer image(10, 5);
    const int far = 100'000'000;
    EXPECT_EQ(fill_quad(image, {{{-far, -far}, {far, -far}, {far, far}, {-far, far}}}, kWhite), 50);
    EXPECT_TRUE(looks_like(image, std::vector<std::string>(5, "++++++++++")));
}

TEST(FillQuad, QuadOutsideTheBufferTestsNothing) {
    Framebuffer image(10, 5);
    EXPECT_EQ(fill_quad(image, {{{12, 1}, {20, 1}, {20, 3}, {12, 3}}}, kWhite), 0);
    EXPECT_EQ(fill_quad(image, {{{-9, -9}, {-2, -9}, {-2, -1}, {-9, -1}}}, kWhite), 0);
    EXPECT_EQ(image, Framebuffer(10, 5));
}

TEST(FillQuad, ZeroAreaQuadsDrawNothing) {
    EXPECT_EQ(quad_on_10x5({{{4, 2}, {4, 2}, {4, 2}, {4, 2}}}), Framebuffer(10, 5));
    EXPECT_EQ(quad_on_10x5({{{2, 3}, {7, 3}, {7, 3}, {2, 3}}}), Framebuffer(10, 5));
    EXPECT_EQ(quad_on_10x5({{{1, 1}, {3, 2}, {5, 3}, {7, 4}}}), Framebuffer(10, 5));
}

TEST(FillQuad, QuadWithARepeatedCornerFillsItsTriangle) {
    EXPECT_TRUE(looks_like(quad_on_10x5({{{0, 0}, {6, 0}, {6, 0}, {0, 3}}}),
                           {"+++++++...", "+++++.....", "+++.......", "+.........", ".........."}));
}

TEST(FillQuad, CornersBeyondTheExactRangeDrawNothing) {
    Framebuffer image(10, 5);
    const int beyond = raster::kMaxFillCoordinate + 1;
    EXPECT_EQ(fill_quad(image, {{{-beyond, 0}, {5, 0}, {5, 4}, {0, 4}}}, kWhite), 0);
    EXPECT_EQ(image, Framebuffer(10, 5));
}
