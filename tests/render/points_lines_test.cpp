// Points drawn as round splats and segments as wide lines, depth-tested with the surfaces
// (doc/conventions.md#points-and-lines).
#include <raster/image/colour.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

const raster::LinearMaterial kWhite{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {}};

// An 11 x 11 orthographic view looking along +z: 5 pixels a world unit, the origin at pixel (5, 5).
raster::Scene scene_of(std::shared_ptr<raster::Mesh> mesh, int size = 11) {
    raster::Scene scene{raster::OrthoCamera(size, size), {0, 0, 0}, {}, {}, {}};
    scene.objects.push_back({std::move(mesh), glm::mat4(1.0F), kWhite, raster::ShadingMethod::phong});
    return scene;
}

// Vertices without normals drawn as points and segments.
std::shared_ptr<raster::Mesh> dots(std::vector<glm::vec3> positions) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->normals.assign(positions.size(), glm::vec3(0.0F));
    mesh->positions = std::move(positions);
    return mesh;
}

// The scene in its square view, `size` pixels a side (the camera's).
Framebuffer drawn(const raster::Scene& scene, raster::RenderOptions options = {}) {
    const int size = static_cast<int>(std::lround(scene.camera.scale() * 2.0)) + 1;
    Framebuffer image(size, size);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, options);
    return image;
}

// '#' where the green channel is full, '.' where it is 0, '+' between.
std::vector<std::string> picture(const Framebuffer& image) {
    std::vector<std::string> rows;
    for (int y = 0; y < image.height(); ++y) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) {
            const int g = image.pixel(x, y).g;
            row += g == 255 ? '#' : g == 0 ? '.' : '+';
        }
        rows.push_back(row);
    }
    return rows;
}

// The share of each pixel that is white, in linear light, summed over the image.
double white_area(const Framebuffer& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) sum += raster::linear_from_srgb_channel(image.pixel(x, y).g / 255.0);
    }
    return sum;
}

}  // namespace

TEST(PointSplat, IsRoundAndCoversItsDiameter) {
    auto mesh = dots({{0.0F, 0.0F, 0.0F}});
    mesh->points = {0};
    raster::Scene scene = scene_of(mesh);
    scene.points_and_lines.point_size = 7.0;  // radius 3.5 around pixel (5, 5)
    const std::vector<std::string> expected{"...........", "...........", "....###....", "...#####...",
                                            "..#######..", "..#######..", "..#######..", "...#####...",
                                            "....###....", "...........", "..........."};
    // Rows 4 and 6 reach 3.35 pixels out, rows 3 and 7 2.87, rows 2 and 8 1.8: 7, 5 and 3 pixels.
    EXPECT_EQ(picture(drawn(scene)), expected);
}

TEST(PointSplat, EdgesAreAntiAliasedByTheSamplesAndTheAreaIsTheDisc) {
    auto mesh = dots({{0.0F, 0.0F, 0.0F}});
    mesh->points = {0};
    raster::Scene scene = scene_of(mesh);
    scene.points_and_lines.point_size = 7.0;
    const Framebuffer image = drawn(scene, {.samples = 16});
    const double disc = std::numbers::pi * 3.5 * 3.5;
    EXPECT_NEAR(white_area(image), disc, disc * 0.04);
    int partial = 0;
    for (const std::string& row : picture(image)) partial += static_cast<int>(std::count(row.begin(), row.end(), '+'));
    EXPECT_GE(partial, 12);  // the rim
    EXPECT_EQ(image.pixel(5, 5), (raster::Rgb{255, 255, 255}));
}

TEST(PointSplat, ATinyPointStillShowsItsPixel) {
    auto mesh = dots({{0.1F, 0.1F, 0.0F}});  // half a pixel off the centre (5.5, 4.5)
    mesh->points = {0};
    raster::Scene scene = scene_of(mesh);
    scene.points_and_lines.point_size = 1.0;
    for (const int samples : {1, 4}) EXPECT_GT(white_area(drawn(scene, {.samples = samples})), 0.0) << samples;
}

TEST(WideLine, IsOfItsWidthAndAntiAliased) {
    // From pixel (1, 5.5) to (9, 5.5): 3 wide, rows 4 to 7 share it, half a row each at the edges.
    auto mesh = dots({{-0.8F, -0.1F, 0.0F}, {0.8F, -0.1F, 0.0F}});
    mesh->segments = {{0, 1}};
    raster::Scene scene = scene_of(mesh);
    scene.points_and_lines.line_width = 3.0;
    const Framebuffer image = drawn(scene, {.samples = 16});
    double column = 0.0;
    for (int y = 0; y < 11; ++y) column += raster::linear_from_srgb_channel(image.pixel(5, y).g / 255.0);
    EXPECT_NEAR(column, 3.0, 0.05);
    const std::vector<std::string> rows = picture(image);
    EXPECT_EQ(rows[3], "...........");
    EXPECT_EQ(rows[4].substr(2, 7), "+++++++");  // the edges, half covered
    EXPECT_EQ(rows[5].substr(1, 9), "#########");
    EXPECT_EQ(rows[6].substr(1, 9), "#########");
    EXPECT_EQ(rows[7].substr(2, 7), "+++++++");
    EXPECT_EQ(rows[8], "...........");
}

TEST(WideLine, ADiagonalKeepsItsWidthAcrossIt) {
    auto mesh = dots({{-1.0F, -0.7F, 0.0F}, {1.0F, 0.7F, 0.0F}});  // slope 0.7: each column cuts it elsewhere
    mesh->segments = {{0, 1}};
    raster::Scene scene = scene_of(mesh, 41);  // 20 pixels a unit
    scene.points_and_lines.line_width = 2.0;
    const Framebuffer image = drawn(scene, {.samples = 16});
    // A vertical cut through a line of width w and slope m is w sqrt(1 + m^2) long: the mean of 21 columns.
    double area = 0.0;
    for (int x = 10; x <= 30; ++x) {
        for (int y = 0; y < 41; ++y) area += raster::linear_from_srgb_channel(image.pixel(x, y).g / 255.0);
    }
    EXPECT_NEAR(area / 21.0, 2.0 * std::sqrt(1.0 + 0.7 * 0.7), 0.05);
}

TEST(PointsAndLines, SizesOutOfRangeAreRefused) {
    auto mesh = dots({{0.0F, 0.0F, 0.0F}});
    mesh->points = {0};
    raster::Scene scene = scene_of(mesh);
    Framebuffer image(11, 11);
    raster::DepthBuffer depth;
    for (const double wrong : {0.5, 65.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        scene.points_and_lines.point_size = wrong;
        EXPECT_THROW(raster::render(image, scene, depth), std::invalid_argument) << wrong;
    }
    scene.points_and_lines.point_size.reset();
    for (const double wrong : {0.25, 65.0, std::nan("")}) {
        scene.points_and_lines.line_width = wrong;
        EXPECT_THROW(raster::render(image, scene, depth), std::invalid_argument) << wrong;
    }
}

TEST(PointsAndLines, IndicesOutOfRangeAreRefused) {
    auto mesh = dots({{0.0F, 0.0F, 0.0F}});
    mesh->points = {1};
    Framebuffer image(11, 11);
    raster::DepthBuffer depth;
    EXPECT_THROW(raster::render(image, scene_of(mesh), depth), std::invalid_argument);
    mesh->points = {};
    mesh->segments = {{0, 7}};
    EXPECT_THROW(raster::render(image, scene_of(mesh), depth), std::invalid_argument);
}

TEST(PointsAndLines, AutomaticSizeIsTwoAndAHalfSpacingsOnScreen) {
    EXPECT_DOUBLE_EQ(raster::automatic_point_size(400.0, 100), 5.0);
    EXPECT_DOUBLE_EQ(raster::automatic_point_size(1e6, 1), 16.0);
    EXPECT_DOUBLE_EQ(raster::automatic_point_size(1.0, 1000000), 1.0);
    EXPECT_DOUBLE_EQ(raster::automatic_point_size(0.0, 0), 1.0);
}
