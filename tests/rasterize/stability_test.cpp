// Where each raster method breaks, and proof that the product's default does not.
#include "corpus.hpp"
#include "measures.hpp"

#include <raster/geometry/cube.hpp>
#include <raster/rasterize/draw_cube.hpp>
#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/line.hpp>
#include <raster/scenes/palette.hpp>
#include <raster/scenes/scenes.hpp>

#include <cmath>
#include <limits>
#include <gtest/gtest.h>

namespace {

const lab::FillMethod& fill_method(std::string_view id) {
    for (const lab::FillMethod& method : lab::fill_methods()) {
        if (method.id == id) return method;
    }
    throw std::invalid_argument("no fill method " + std::string(id));
}

const lab::LineMethod& line_method(std::string_view id) {
    for (const lab::LineMethod& method : lab::line_methods()) {
        if (method.id == id) return method;
    }
    throw std::invalid_argument("no line method " + std::string(id));
}

bool ends_with(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

TEST(DefaultFill, MatchesTheReferenceOnEveryCorpusAtEveryOffset) {
    for (const lab::PolygonCorpus& corpus : lab::polygon_corpora()) {
        const lab::FillAccuracy result = lab::measure_polygons(lab::product_fill(), corpus);
        EXPECT_GT(result.reference_pixels, 0) << corpus.name;
        EXPECT_EQ(result.mismatches, 0) << corpus.name;
    }
}

TEST(DefaultFill, CoversEveryClosedMeshExactlyOnceUpToAMillionPixelsAway) {
    for (const lab::MeshCase& mesh : lab::mesh_cases()) {
        const lab::FillAccuracy result = lab::measure_mesh(lab::product_fill(), mesh);
        EXPECT_EQ(result.mismatches, 0) << mesh.name;
        EXPECT_EQ(result.cracks, 0) << mesh.name;
        EXPECT_EQ(result.double_hits, 0) << mesh.name;
    }
}

TEST(SeedFill, HitsSharedEdgesTwiceAtEveryOffset) {
    for (const lab::MeshCase& mesh : lab::mesh_cases()) {
        EXPECT_GT(lab::measure_mesh(fill_method("seed-bbox-float"), mesh).double_hits, 0) << mesh.name;
    }
}

TEST(FloatEdgeFunctions, HoldNearTheOriginAndCrackThreeHundredThousandPixelsAway) {
    for (const lab::MeshCase& mesh : lab::mesh_cases()) {
        const lab::FillAccuracy result = lab::measure_mesh(fill_method("edge-float"), mesh);
        if (ends_with(mesh.name, "@0") || ends_with(mesh.name, "@3000")) {
            EXPECT_EQ(result.cracks + result.double_hits, 0) << mesh.name;
        } else {
            EXPECT_GT(result.cracks, 0) << mesh.name;
        }
    }
}

TEST(FourBitSubpixels, AreExactOnTheSixteenthGridAndMissOnTheFinerOne) {
    for (const lab::PolygonCorpus& corpus : lab::polygon_corpora()) {
        const lab::FillAccuracy result = lab::measure_polygons(fill_method("edge-fixed4"), corpus);
        if (corpus.name.starts_with("grid16")) {
            EXPECT_EQ(result.mismatches, 0) << corpus.name;
        } else if (corpus.name.starts_with("grid256")) {
            EXPECT_GT(result.mismatches, 0) << corpus.name;
        }
    }
}

TEST(DefaultFill, WobblesLessThanTheSeedWhenATriangleCreepsSixteenthsOfAPixel) {
    for (const std::int64_t offset : lab::kOffsets) {
        const double product = lab::measure_motion(lab::product_fill(), offset);
        const double seed = lab::measure_motion(fill_method("seed-bbox-float"), offset);
        EXPECT_LT(product, 0.2) << offset;
        EXPECT_GT(seed, 1.5 * product) << offset;
    }
}

TEST(DefaultFill, WorkFollowsTheVisibleRowsNotTheTrianglesSize) {
    raster::Framebuffer image(10, 10);
    for (const std::int32_t reach : {1'000, 100'000, 2'000'000}) {
        const std::int32_t r = reach * raster::kSubpixelOne;
        const std::vector<raster::SubpixelPoint> triangle{{-r, -r}, {r, -r / 2}, {0, r}};
        EXPECT_LE(raster::fill_convex(image, triangle, raster::kWhite), 10) << reach;
    }
}

TEST(DefaultLine, WorkFollowsTheVisiblePixelsWhileTheSeedWalksTheWholeSegment) {
    raster::Framebuffer image(10, 10);
    for (const int reach : {1'000, 100'000, 1'000'000}) {
        EXPECT_EQ(lab::product_line().draw(image, {0, 0}, {-reach, 5}, {reach, 3}), 10) << reach;
        EXPECT_EQ(line_method("seed-float-dda").draw(image, {0, 0}, {-reach, 5}, {reach, 3}), 2 * reach + 1) << reach;
    }
}

TEST(DefaultLine, MatchesTheReferenceOnEverySegmentCorpus) {
    for (const lab::SegmentCorpus& corpus : lab::segment_corpora()) {
        const lab::LineAccuracy result = lab::measure_segments(lab::product_line(), corpus);
        EXPECT_EQ(result.mismatches, 0) << corpus.name;
        EXPECT_EQ(result.outside_neighbourhood, 0) << corpus.name;
        EXPECT_EQ(result.max_count_difference, 0) << corpus.name;
    }
}

TEST(EveryLineMethod, StaysWithinOnePixelOfTheReference) {
    for (const lab::LineMethod& method : lab::line_methods()) {
        for (const lab::SegmentCorpus& corpus : lab::segment_corpora()) {
            const lab::LineAccuracy result = lab::measure_segments(method, corpus);
            EXPECT_EQ(result.outside_neighbourhood, 0) << method.id << " " << corpus.name;
            EXPECT_LE(result.max_count_difference, 1) << method.id << " " << corpus.name;
            EXPECT_LT(result.max_distance, 1.0) << method.id << " " << corpus.name;
        }
    }
}

TEST(EveryFillMethod, SkipsNonFiniteCornersWithoutWriting) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const lab::FillMethod& method : lab::fill_methods()) {
        for (const glm::dvec2 bad : {glm::dvec2(nan, 2), glm::dvec2(3, nan), glm::dvec2(inf, 1), glm::dvec2(1, -inf)}) {
            lab::Coverage coverage({0, 0, 16, 16});
            const std::vector<glm::dvec2> corners{{1, 1}, bad, {12, 9}};
            method.fill(corners, coverage);
            EXPECT_EQ(coverage.total(), 0) << method.id;
        }
    }
}

TEST(DefaultFill, ZeroAreaSliverAndCollinearShapesFollowTheReference) {
    const lab::PixelRect window{0, 0, 16, 16};
    const auto at = [](double x, double y) {
        return lab::ExactPoint{static_cast<std::int64_t>(x * 1024), static_cast<std::int64_t>(y * 1024)};
    };
    const std::vector<lab::Polygon> shapes{
        {at(2, 2), at(2, 2), at(2, 2)},                     // a point
        {at(1, 1), at(5, 5), at(9, 9)},                     // collinear through centres
        {at(1, 1), at(14, 2), at(14, 2), at(1, 1)},         // a quad folded onto a segment
        {at(1, 3), at(14, 3.00390625), at(1, 3.00390625)},  // a sliver 1/256 px tall on a row of centres
        {at(3, 1), at(3.00390625, 14), at(3, 14)},          // a sliver 1/256 px wide on a column of centres
    };
    for (const lab::Polygon& shape : shapes) {
        const lab::PolygonCorpus corpus{"shape", window, {shape}};
        EXPECT_EQ(lab::measure_polygons(lab::product_fill(), corpus).mismatches, 0);
    }
}

TEST(TumblingCube, FacesSeenExactlyEdgeOnAtQuarterTurnsDrawNothing) {
    const raster::OrthoCamera camera(raster::kSceneWidth, raster::kSceneHeight);
    int edge_on = 0;
    for (const int frame : {0, 90, 180, 270}) {
        const raster::Cube cube = raster::Cube().posed(raster::tumble_pose(frame, raster::kAnimationFrameCount));
        const auto toward = raster::faces_toward_camera(camera, cube);
        for (std::size_t slot = 0; slot < cube.faces().size(); ++slot) {
            if (std::abs(cube.faces()[slot].normal.z) > 1e-5F) continue;
            ++edge_on;
            EXPECT_EQ(std::count(toward.begin(), toward.end(), slot), 0) << "frame " << frame << " face " << slot;
            raster::Framebuffer image(raster::kSceneWidth, raster::kSceneHeight);
            std::vector<raster::SubpixelPoint> corners;
            for (const std::size_t corner : cube.faces()[slot].corners) {
                corners.push_back(*camera.subpixel_from_world(cube.corners()[corner]));
            }
            raster::fill_convex(image, corners, raster::kWhite);
            EXPECT_EQ(image, raster::Framebuffer(raster::kSceneWidth, raster::kSceneHeight))
                << "frame " << frame << " face " << slot;
        }
    }
    EXPECT_GE(edge_on, 4 * 4);  // four side faces are edge-on in each quarter-turn pose
}

TEST(TumblingCube, NonFinitePoseDrawsNothing) {
    raster::Framebuffer image(64, 48);
    glm::mat4 pose = raster::tumble_pose(10, 360);
    pose[1][1] = std::numeric_limits<float>::quiet_NaN();
    for (const raster::CubeStyle style : {raster::CubeStyle::filled, raster::CubeStyle::wireframe}) {
        raster::render_cube(image, pose, style, raster::kWhite);
        EXPECT_EQ(image, raster::Framebuffer(64, 48));
    }
}
