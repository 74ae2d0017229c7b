#include <raster/rasterize/fill.hpp>

#include "support/picture.hpp"

#include <algorithm>
#include <vector>
#include <gtest/gtest.h>

using raster::fill_convex;
using raster::Framebuffer;
using raster::SubpixelPoint;
using test_support::looks_like;
using Polygon = std::vector<SubpixelPoint>;

namespace {

constexpr raster::Rgb kWhite{255, 255, 255};

// A corner at pixel coordinates (x, y), which may fall between pixel centres.
SubpixelPoint at(double x, double y) {
    return {static_cast<std::int32_t>(x * raster::kSubpixelOne), static_cast<std::int32_t>(y * raster::kSubpixelOne)};
}

Framebuffer filled_10x5(const Polygon& corners) {
    Framebuffer image(10, 5);
    fill_convex(image, corners, kWhite);
    return image;
}

Polygon starting_at(Polygon corners, std::size_t first) {
    std::rotate(corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(first), corners.end());
    return corners;
}

}  // namespace

TEST(FillConvex, RectangleOnPixelCentresTakesItsTopAndLeftEdgesOnly) {
    EXPECT_TRUE(looks_like(filled_10x5({at(2, 1), at(7, 1), at(7, 3), at(2, 3)}),
                           {"..........", "..+++++...", "..+++++...", "..........", ".........."}));
}

TEST(FillConvex, RectangleBetweenCentresCoversTheCentresInside) {
    EXPECT_TRUE(looks_like(filled_10x5({at(1.5, 0.5), at(6.5, 0.5), at(6.5, 3.5), at(1.5, 3.5)}),
                           {"..........", "..+++++...", "..+++++...", "..+++++...", ".........."}));
}

TEST(FillConvex, SlantedQuadCoversCentresByTheTopLeftRule) {
    EXPECT_TRUE(looks_like(filled_10x5({at(2, 3), at(7, 3), at(8, 1), at(1, 1)}),
                           {"..........", ".+++++++..", "..++++++..", "..........", ".........."}));
}

TEST(FillConvex, EitherWindingAndEveryStartingCornerFillTheSamePixels) {
    const Polygon slanted{at(2.25, 3.5), at(7, 3.5), at(8.5, 0.75), at(1, 1)};
    const Framebuffer expected = filled_10x5(slanted);
    for (std::size_t first = 0; first < slanted.size(); ++first) {
        Polygon reversed = starting_at(slanted, first);
        EXPECT_EQ(filled_10x5(reversed), expected) << "start " << first;
        std::reverse(reversed.begin(), reversed.end());
        EXPECT_EQ(filled_10x5(reversed), expected) << "reversed, start " << first;
    }
}

TEST(FillConvex, TwoTrianglesSharingAnEdgeCoverEveryPixelExactlyOnce) {
    const Polygon left{at(0.5, 0.25), at(8.75, 4.5), at(0.5, 4.5)};
    const Polygon right{at(0.5, 0.25), at(8.75, 0.25), at(8.75, 4.5)};
    std::vector<int> hits(50, 0);
    const raster::PixelRect clip{0, 0, 10, 5};
    for (const Polygon& triangle : {left, right}) {
        raster::rasterize_convex(triangle, clip, [&](raster::Span span) {
            for (int x = span.x_begin; x < span.x_end; ++x) ++hits[static_cast<std::size_t>(span.y * 10 + x)];
        });
    }
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 10; ++x) {
            const bool inside = x >= 1 && x <= 8 && y >= 1 && y <= 4;
            EXPECT_EQ(hits[static_cast<std::size_t>(y * 10 + x)], inside ? 1 : 0) << "pixel (" << x << ", " << y << ")";
        }
    }
}

TEST(FillConvex, TriangleLeavesOutCentresOnItsRightAndBottomEdges) {
    EXPECT_TRUE(looks_like(filled_10x5({at(0, 0), at(6, 0), at(0, 3)}),
                           {"++++++....", "++++......", "++........", "..........", ".........."}));
}

TEST(FillConvex, ClipsAtTheBufferAndExaminesOnlyVisibleRows) {
    Framebuffer image(10, 5);
    EXPECT_EQ(fill_convex(image, Polygon{at(-5, -5), at(4.5, -5), at(4.5, 2.5), at(-5, 2.5)}, kWhite), 3);
    EXPECT_TRUE(looks_like(image, {"+++++.....", "+++++.....", "+++++.....", "..........", ".........."}));
}

TEST(FillConvex, HugePolygonCostsOneStepPerVisibleRow) {
    Framebuffer image(10, 5);
    const double far = 2'000'000;
    EXPECT_EQ(fill_convex(image, Polygon{at(-far, -far), at(far, -far), at(far, far), at(-far, far)}, kWhite), 5);
    EXPECT_TRUE(looks_like(image, std::vector<std::string>(5, "++++++++++")));
}

TEST(FillConvex, PolygonOutsideTheBufferExaminesNothing) {
    Framebuffer image(10, 5);
    EXPECT_EQ(fill_convex(image, Polygon{at(12, 1), at(20, 1), at(20, 3)}, kWhite), 0);
    EXPECT_EQ(fill_convex(image, Polygon{at(-9, -9), at(-2, -9), at(-2, -1)}, kWhite), 0);
    EXPECT_EQ(image, Framebuffer(10, 5));
}

TEST(FillConvex, ZeroAreaPolygonsDrawNothing) {
    EXPECT_EQ(filled_10x5({at(4, 2), at(4, 2), at(4, 2), at(4, 2)}), Framebuffer(10, 5));
    EXPECT_EQ(filled_10x5({at(2, 3), at(7, 3), at(7, 3), at(2, 3)}), Framebuffer(10, 5));
    EXPECT_EQ(filled_10x5({at(1, 1), at(3, 2), at(5, 3), at(7, 4)}), Framebuffer(10, 5));
    EXPECT_EQ(filled_10x5({at(1, 1), at(1, 1)}), Framebuffer(10, 5));
}

TEST(FillConvex, SliverCoversOnlyTheCentresItReallyContains) {
    // A triangle 1/256 px wide along x = 3 holds the centres of column 3 on its left edge; the
    // top vertex also lies on the right edge, which the rule leaves out.
    EXPECT_TRUE(looks_like(filled_10x5({at(3, 0), at(3 + 1.0 / 256, 4.5), at(3, 4.5)}),
                           {"..........", "...+......", "...+......", "...+......", "...+......"}));
    EXPECT_EQ(filled_10x5({at(3.5, 0), at(3.5 + 1.0 / 256, 4.5), at(3.5, 4.5)}), Framebuffer(10, 5));
}

TEST(FillConvex, OriginPlacesTheBufferAnywhereInThePlane) {
    Framebuffer image(10, 5);
    const glm::ivec2 origin{300'000, -40'000};
    fill_convex(image, Polygon{at(300'002, -39'999), at(300'007, -39'999), at(300'007, -39'997), at(300'002, -39'997)},
                kWhite, origin);
    EXPECT_EQ(image, filled_10x5({at(2, 1), at(7, 1), at(7, 3), at(2, 3)}));
}

TEST(FillConvex, SignedAreaIsPositiveForCornersClockwiseOnScreen) {
    EXPECT_GT(raster::twice_signed_area(Polygon{at(0, 0), at(1, 0), at(1, 1)}), 0);
    EXPECT_LT(raster::twice_signed_area(Polygon{at(0, 0), at(1, 1), at(1, 0)}), 0);
    EXPECT_EQ(raster::twice_signed_area(Polygon{at(0, 0), at(1, 1), at(2, 2)}), 0);
}

TEST(FillConvex, ATriangleGivenAsFourCornersWithOneRepeatedDrawsTheTriangle) {
    const Polygon triangle{at(1, 0.5), at(8.5, 0.5), at(1, 4.5)};
    const Framebuffer expected = filled_10x5(triangle);
    EXPECT_TRUE(looks_like(expected, {"..........", ".+++++++..", ".+++++....", ".+++......", ".+........"}));
    for (std::size_t repeated = 0; repeated < triangle.size(); ++repeated) {
        Polygon quad = triangle;
        quad.insert(quad.begin() + static_cast<std::ptrdiff_t>(repeated), triangle[repeated]);
        EXPECT_EQ(filled_10x5(quad), expected) << "corner " << repeated << " repeated";
        quad.insert(quad.begin() + static_cast<std::ptrdiff_t>(repeated), triangle[repeated]);
        EXPECT_EQ(filled_10x5(quad), expected) << "corner " << repeated << " listed three times";
    }
}

TEST(FillConvex, ASquareSplitIntoDegenerateQuadsCoversEachPixelOnce) {
    // Two triangles of an 8x8 square, each given as a quad that repeats its last corner.
    Framebuffer image(10, 10);
    const Polygon upper{at(1, 1), at(9, 1), at(9, 9), at(9, 9)};
    const Polygon lower{at(1, 1), at(9, 9), at(1, 9), at(1, 1)};
    int covered = 0;
    for (const Polygon* half : {&upper, &lower}) {
        raster::rasterize_convex(*half, {0, 0, 10, 10}, [&](raster::Span span) {
            covered += span.x_end - span.x_begin;
            image.fill_row(span.y, span.x_begin, span.x_end, kWhite);
        });
    }
    EXPECT_EQ(covered, 64) << "every pixel of the square once";
    Framebuffer square(10, 10);
    fill_convex(square, Polygon{at(1, 1), at(9, 1), at(9, 9), at(1, 9)}, kWhite);
    EXPECT_EQ(image, square);
}

TEST(FillConvex, CollinearRunsOfCornersDrawTheSamePolygon) {
    const Polygon rectangle{at(1.5, 0.5), at(7.5, 0.5), at(7.5, 3.5), at(1.5, 3.5)};
    const Polygon with_midpoints{at(1.5, 0.5), at(3, 0.5),   at(5.25, 0.5), at(7.5, 0.5),
                                 at(7.5, 2),   at(7.5, 3.5), at(4, 3.5),    at(1.5, 3.5)};
    EXPECT_EQ(filled_10x5(with_midpoints), filled_10x5(rectangle));
    const Polygon triangle{at(1, 0.5), at(8.5, 0.5), at(1, 4.5)};
    const Polygon with_points_on_the_slant{at(1, 0.5), at(8.5, 0.5), at(4.75, 2.5), at(1, 4.5)};
    EXPECT_EQ(filled_10x5(with_points_on_the_slant), filled_10x5(triangle));
}

TEST(FillConvex, AllCornersEqualDrawNothing) {
    EXPECT_EQ(filled_10x5({at(3, 2), at(3, 2), at(3, 2), at(3, 2)}), Framebuffer(10, 5));
}
