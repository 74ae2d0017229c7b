#include <raster/rasterize/draw_cube.hpp>
#include <raster/rasterize/line.hpp>
#include <raster/scenes/palette.hpp>
#include <raster/scenes/scenes.hpp>

#include "support/picture.hpp"

#include <limits>
#include <string>
#include <vector>
#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/scalar_constants.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;
using test_support::looks_like;

namespace {
const std::map<char, raster::Rgb> kFaceLegend{
    {'B', raster::kCubeFacePalette[raster::kNearFace]},  {'R', raster::kCubeFacePalette[raster::kFarFace]},
    {'A', raster::kCubeFacePalette[raster::kRightFace]}, {'I', raster::kCubeFacePalette[raster::kLeftFace]},
    {'J', raster::kCubeFacePalette[raster::kTopFace]},   {'O', raster::kCubeFacePalette[raster::kBottomFace]}};
}

TEST(DrawCube, UnitCubeAtIdentityIsOneBlueSquare) {
    Framebuffer image(11, 7);
    raster::render_unit_cube(image);
    EXPECT_TRUE(looks_like(
        image,
        {"...........", "...........", "....BBB....", "....BBB....", "....BBB....", "...........", "..........."},
        kFaceLegend));
}

TEST(DrawCube, UnitCubeSeenFromBehindIsOneRedSquare) {
    Framebuffer image(11, 7);
    raster::render_cube(image, glm::rotate(glm::mat4(1.0F), glm::pi<float>(), glm::vec3(0, 1, 0)),
                        raster::CubeStyle::filled, raster::kWhite);
    EXPECT_EQ(test_support::to_ascii_art(image, kFaceLegend).find('B'), std::string::npos);
    EXPECT_NE(test_support::to_ascii_art(image, kFaceLegend).find('R'), std::string::npos);
}

TEST(DrawCube, UnitCubeWireframeIsTheNearSquareOutline) {
    Framebuffer image(11, 7);
    raster::render_cube(image, glm::mat4(1.0F), raster::CubeStyle::wireframe, raster::kWhite);
    EXPECT_TRUE(looks_like(image, {"...........", "...........", "....++++...", "....+..+...", "....+..+...",
                                   "....++++...", "..........."}));
}

TEST(DrawCube, CulledWireframeDrawsOnlyEdgesOfFrontFaces) {
    Framebuffer all(80, 60);
    Framebuffer culled(80, 60);
    raster::render_still_cube(all, raster::CubeStyle::wireframe);
    raster::render_still_cube(culled, raster::CubeStyle::culled_wireframe);
    int only_in_all = 0;
    for (int y = 0; y < 60; ++y) {
        for (int x = 0; x < 80; ++x) {
            EXPECT_FALSE(culled.pixel(x, y) != raster::kBlack && all.pixel(x, y) == raster::kBlack);
            only_in_all += all.pixel(x, y) != raster::kBlack && culled.pixel(x, y) == raster::kBlack;
        }
    }
    EXPECT_GT(only_in_all, 0);
}

TEST(DrawCube, FilledStillCubeShowsNearRightAndBottomFacesOnly) {
    Framebuffer image(80, 60);
    raster::render_still_cube(image, raster::CubeStyle::filled);
    const std::string art = test_support::to_ascii_art(image, kFaceLegend);
    for (const char face : {'B', 'A', 'O'}) EXPECT_NE(art.find(face), std::string::npos) << face;
    for (const char face : {'R', 'I', 'J', '+'}) EXPECT_EQ(art.find(face), std::string::npos) << face;
}

namespace {

// The face slots whose palette colour appears in a filled render.
std::vector<std::size_t> slots_painted(const Framebuffer& image) {
    std::vector<std::size_t> slots;
    for (std::size_t slot = 0; slot < raster::kCubeFacePalette.size(); ++slot) {
        bool seen = false;
        for (int y = 0; y < image.height() && !seen; ++y) {
            for (int x = 0; x < image.width() && !seen; ++x) seen = image.pixel(x, y) == raster::kCubeFacePalette[slot];
        }
        if (seen) slots.push_back(slot);
    }
    return slots;
}

}  // namespace

TEST(DrawCube, CullingFillingAndCulledWireframesFollowOneFacingRuleEvenForSingularAndNaNPoses) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    const glm::mat4 tilted = raster::still_cube_pose();
    std::vector<std::pair<std::string, glm::mat4>> poses{
        {"flattened along z", glm::scale(tilted, glm::vec3(1, 1, 0))},
        {"flattened along x", glm::scale(tilted, glm::vec3(0, 1, 1))},
        {"squashed to a line", glm::scale(tilted, glm::vec3(0, 1, 0))},
        {"zero matrix", glm::mat4(0.0F)},
        {"flat and facing away", glm::scale(glm::mat4(1.0F), glm::vec3(-1, 1, 0))},
        {"NaN entry", tilted},
        {"infinite entry", tilted},
        {"quarter turn", raster::tumble_pose(90, 360)},
        {"still pose", tilted}};
    poses[5].second[0][2] = kNaN;
    poses[6].second[2][2] = kInfinity;
    const raster::OrthoCamera camera(80, 60);
    for (const auto& [name, pose] : poses) {
        const raster::Cube cube = raster::Cube().posed(pose);
        const std::vector<std::size_t> toward = raster::faces_toward_camera(camera, cube);
        Framebuffer filled(80, 60);
        raster::render_cube(filled, pose, raster::CubeStyle::filled, raster::kWhite);
        EXPECT_EQ(slots_painted(filled), toward) << name;
        Framebuffer culled(80, 60);
        raster::render_cube(culled, pose, raster::CubeStyle::culled_wireframe, raster::kWhite);
        Framebuffer expected(80, 60);
        for (const raster::Edge& edge : cube.edges_of(toward)) {
            raster::draw_line(expected, *camera.pixel_from_world(cube.corners()[edge.from]),
                              *camera.pixel_from_world(cube.corners()[edge.to]), raster::kWhite);
        }
        EXPECT_EQ(culled, expected) << name;
    }
    const raster::Cube flat = raster::Cube().posed(glm::scale(glm::mat4(1.0F), glm::vec3(1, 1, 0)));
    EXPECT_EQ(raster::faces_toward_camera(camera, flat), std::vector<std::size_t>{raster::kNearFace})
        << "a cube flattened onto the screen shows its near face, though its normals are not finite";
}
