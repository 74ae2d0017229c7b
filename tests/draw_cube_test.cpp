#include <raster/draw_cube.hpp>
#include <raster/palette.hpp>
#include <raster/scenes.hpp>

#include "support/picture.hpp"

#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/scalar_constants.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;
using test_support::looks_like;

namespace {
const std::map<char, raster::Rgb> kFaceLegend{
    {'B', raster::kCubeFacePalette[raster::kNearFace]},
    {'R', raster::kCubeFacePalette[raster::kFarFace]},
    {'A', raster::kCubeFacePalette[raster::kRightFace]},
    {'I', raster::kCubeFacePalette[raster::kLeftFace]},
    {'J', raster::kCubeFacePalette[raster::kTopFace]},
    {'O', raster::kCubeFacePalette[raster::kBottomFace]}};
}

TEST(DrawCube, UnitCubeAtIdentityIsOneBlueSquare) {
    Framebuffer image(11, 7);
    raster::render_unit_cube(image);
    EXPECT_TRUE(looks_like(image,
                           {"...........",
                            "...........",
                            "....BBB....",
                            "....BBB....",
                            "....BBB....",
                            "...........",
                            "..........."},
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
    EXPECT_TRUE(looks_like(image,
                           {"...........",
                            "...........",
                            "....++++...",
                            "....+..+...",
                            "....+..+...",
                            "....++++...",
                            "..........."}));
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
