#include "reference.hpp"

#include <string>
#include <vector>
#include <gtest/gtest.h>

using lab::Coverage;
using lab::ExactPoint;

namespace {

// A corner at pixel coordinates given in sixteenths of a pixel.
ExactPoint sixteenths(std::int64_t x, std::int64_t y) { return {x * lab::kExactOne / 16, y * lab::kExactOne / 16}; }
ExactPoint pixel(std::int64_t x, std::int64_t y) { return sixteenths(16 * x, 16 * y); }

std::vector<std::string> picture(const Coverage& coverage) {
    std::vector<std::string> rows;
    const lab::PixelRect& r = coverage.rect();
    for (int y = r.y; y < r.y + r.height; ++y) {
        std::string row;
        for (int x = r.x; x < r.x + r.width; ++x) {
            const int hits = coverage.at(x, y);
            row += hits == 0 ? '.' : static_cast<char>('0' + hits);
        }
        rows.push_back(row);
    }
    return rows;
}

std::vector<std::string> polygon_on_8x5(const std::vector<ExactPoint>& corners) {
    Coverage coverage({0, 0, 8, 5});
    lab::reference_polygon(corners, coverage);
    return picture(coverage);
}

}  // namespace

TEST(ReferencePolygon, SquareOnPixelCentresKeepsTopAndLeftEdgesOnly) {
    EXPECT_EQ(polygon_on_8x5({pixel(1, 1), pixel(4, 1), pixel(4, 3), pixel(1, 3)}),
              (std::vector<std::string>{"........", ".111....", ".111....", "........", "........"}));
}

TEST(ReferencePolygon, CentreOnTheFlatTopEdgeIsInAndOnTheFlatBottomEdgeIsOut) {
    // Top edge y = 1 holds centres (2..4, 1); the bottom edge y = 2 holds (2..4, 2).
    EXPECT_EQ(polygon_on_8x5({sixteenths(24, 16), sixteenths(72, 16), sixteenths(72, 32), sixteenths(24, 32)}),
              (std::vector<std::string>{"........", "..111...", "........", "........", "........"}));
}

TEST(ReferencePolygon, CentreOnALeftEdgeIsInAndOnARightEdgeIsOut) {
    // (2, 2) lies on the left edge and is in; (4, 2) lies on the right edge and is out; the apex
    // (3, 0) lies on both and is out.
    EXPECT_EQ(polygon_on_8x5({pixel(3, 0), pixel(5, 4), pixel(1, 4)}),
              (std::vector<std::string>{"........", "...1....", "..11....", "..111...", "........"}));
}

TEST(ReferencePolygon, WindingDoesNotMatter) {
    const std::vector<ExactPoint> clockwise{sixteenths(5, 3), sixteenths(100, 20), sixteenths(30, 70)};
    const std::vector<ExactPoint> counter{clockwise[2], clockwise[1], clockwise[0]};
    EXPECT_EQ(polygon_on_8x5(clockwise), polygon_on_8x5(counter));
}

TEST(ReferencePolygon, ZeroAreaCoversNothing) {
    EXPECT_EQ(polygon_on_8x5({pixel(1, 1), pixel(3, 2), pixel(5, 3)}), std::vector<std::string>(5, "........"));
}

TEST(ReferencePolygon, SharedEdgeCentresGoToExactlyOneOfTwoTriangles) {
    // The diagonal from (1, 0) to (7, 3) passes through the centres (3, 1) and (5, 2).
    Coverage coverage({0, 0, 8, 5});
    lab::reference_polygon(std::vector{pixel(1, 0), pixel(7, 0), pixel(7, 3)}, coverage);
    lab::reference_polygon(std::vector{pixel(1, 0), pixel(7, 3), pixel(1, 3)}, coverage);
    EXPECT_EQ(picture(coverage),
              (std::vector<std::string>{".111111.", ".111111.", ".111111.", "........", "........"}));
}

TEST(ReferencePolygon, ClosedFanCoversEveryCentreOfItsRectangleExactlyOnce) {
    // A rectangle on the 1/16 grid cut into a fan around an interior point, with many centres on
    // the cuts: each centre inside is covered once, none outside.
    const std::vector<ExactPoint> rim{sixteenths(8, 8),    sixteenths(48, 8),  sixteenths(104, 8), sixteenths(104, 40),
                                      sixteenths(104, 72), sixteenths(56, 72), sixteenths(8, 72),  sixteenths(8, 40)};
    const ExactPoint hub = sixteenths(48, 32);
    Coverage coverage({0, 0, 8, 5});
    for (std::size_t i = 0; i < rim.size(); ++i) {
        lab::reference_polygon(std::vector{hub, rim[i], rim[(i + 1) % rim.size()]}, coverage);
    }
    // Centres with 0.5 <= x < 6.5 and 0.5 <= y < 4.5.
    EXPECT_EQ(picture(coverage),
              (std::vector<std::string>{"........", ".111111.", ".111111.", ".111111.", ".111111."}));
}

TEST(ReferencePolygon, VertexSharedByAFanBelongsToExactlyOneTriangle) {
    const ExactPoint hub = pixel(4, 2);
    const std::vector<ExactPoint> rim{pixel(1, 0), pixel(7, 0), pixel(7, 4), pixel(1, 4)};
    Coverage coverage({0, 0, 8, 5});
    for (std::size_t i = 0; i < rim.size(); ++i) {
        lab::reference_polygon(std::vector{hub, rim[i], rim[(i + 1) % rim.size()]}, coverage);
    }
    EXPECT_EQ(coverage.at(4, 2), 1);
    EXPECT_EQ(coverage.total(), 6 * 4);
}

TEST(ReferenceLine, DrawsBothEndsAndOnePixelPerColumn) {
    Coverage coverage({0, 0, 8, 5});
    lab::reference_line({0, 0}, {7, 2}, coverage);
    EXPECT_EQ(picture(coverage),
              (std::vector<std::string>{"11......", "..1111..", "......11", "........", "........"}));
}

TEST(ReferenceLine, BreaksTiesTowardPositiveYThenPositiveX) {
    Coverage shallow({0, 0, 8, 5});
    lab::reference_line({0, 0}, {2, 1}, shallow);  // crosses column 1 at y = 1/2 exactly
    EXPECT_EQ(shallow.at(1, 1), 1);
    EXPECT_EQ(shallow.at(1, 0), 0);
    Coverage steep({0, 0, 8, 5});
    lab::reference_line({2, 0}, {1, 2}, steep);  // crosses row 1 at x = 3/2 exactly
    EXPECT_EQ(steep.at(2, 1), 1);
    EXPECT_EQ(steep.at(1, 1), 0);
}

TEST(ReferenceLine, DiagonalAndSinglePixel) {
    Coverage coverage({0, 0, 8, 5});
    lab::reference_line({1, 4}, {5, 0}, coverage);
    lab::reference_line({7, 4}, {7, 4}, coverage);
    EXPECT_EQ(picture(coverage),
              (std::vector<std::string>{".....1..", "....1...", "...1....", "..1.....", ".1.....1"}));
}
