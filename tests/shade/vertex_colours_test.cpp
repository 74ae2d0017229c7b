// Vertex colours: each corner's colour interpolated in linear light, multiplying the diffuse colour.
#include <raster/geometry/shapes.hpp>
#include <raster/image/colour.hpp>
#include <raster/render/scene.hpp>

#include <cstdlib>
#include <memory>
#include <numbers>
#include <string>
#include <vector>
#include <glm/ext/matrix_transform.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::LinearRgb;

namespace {

// A 2 x 2 square facing the camera and filling a 9 x 9 image, its left corners red and its
// right corners blue, under one light from the camera's side.
Framebuffer red_to_blue(raster::ShadingMethod method, LinearRgb diffuse = {1, 1, 1}) {
    raster::Scene scene{raster::OrthoCamera(9, 9), {0, 0, 0}, {{{0.0F, 0.0F, -1.0F}, 1.0F}}, {}, {}};
    auto square = std::make_shared<raster::Mesh>(
        raster::ground_quad({-1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, 1.0F}, {-1.0F, 0.0F, 1.0F}));
    for (const glm::vec3& p : square->positions)
        square->colours.push_back(p.x < 0.0F ? LinearRgb{1, 0, 0} : LinearRgb{0, 0, 1});
    const glm::mat4 facing_camera = glm::rotate(glm::mat4(1.0F), -std::numbers::pi_v<float> / 2, {1.0F, 0.0F, 0.0F});
    scene.objects.push_back({square, facing_camera, raster::LinearMaterial{{0, 0, 0}, diffuse, {0, 0, 0}, {}}, method});
    Framebuffer image(9, 9);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth);
    return image;
}

// 'R' where red leads blue by more than 16 levels, 'B' the other way, 'm' for a mix, '.' black.
std::vector<std::string> hues(const Framebuffer& image) {
    std::vector<std::string> rows;
    for (int y = 0; y < image.height(); ++y) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb p = image.pixel(x, y);
            row += p.r == 0 && p.b == 0 ? '.' : p.r > p.b + 16 ? 'R' : p.b > p.r + 16 ? 'B' : 'm';
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

TEST(VertexColours, CornersColoursBlendInLinearLightAndMultiplyTheDiffuseColour) {
    // Pixel centres run from the left corners (column 0) to the right ones (column 8, left out by the fill rule).
    std::vector<std::string> expected(8, "RRRRmBBB.");
    expected.emplace_back(".........");
    // Every shading method interpolates the corners' colours; flat lights the facet once but keeps them.
    for (const auto method : {raster::ShadingMethod::unlit, raster::ShadingMethod::flat, raster::ShadingMethod::gouraud,
                              raster::ShadingMethod::phong}) {
        const Framebuffer image = red_to_blue(method);
        EXPECT_EQ(hues(image), expected) << "shading " << static_cast<int>(method);
        // Halfway across, half red and half blue in linear light: 188 each, not sRGB's 128.
        const double left = image.pixel(3, 4).r, right = image.pixel(5, 4).r;
        EXPECT_GT(left, 188.0) << static_cast<int>(method);
        EXPECT_LT(right, 188.0) << static_cast<int>(method);
        EXPECT_NEAR(image.pixel(4, 4).r + image.pixel(4, 4).b, 2 * 188.0, 40.0) << static_cast<int>(method);
    }
    // The diffuse colour multiplies: half the red of the material halves the corners' red light.
    const Framebuffer full = red_to_blue(raster::ShadingMethod::unlit);
    const Framebuffer halved = red_to_blue(raster::ShadingMethod::unlit, {0.5F, 1.0F, 1.0F});
    const double linear_full = raster::linear_from_srgb_channel(full.pixel(0, 4).r / 255.0);
    const double linear_halved = raster::linear_from_srgb_channel(halved.pixel(0, 4).r / 255.0);
    EXPECT_NEAR(linear_halved, 0.5 * linear_full, 0.01);
    EXPECT_EQ(halved.pixel(8 - 1, 4).b, full.pixel(8 - 1, 4).b);
}

TEST(VertexColours, AMeshWhoseColoursDoNotMatchItsPositionsIsRefused) {
    raster::Scene scene{raster::OrthoCamera(9, 9), {0, 0, 0}, {}, {}, {}};
    auto square = std::make_shared<raster::Mesh>(
        raster::ground_quad({-1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, 1.0F}, {-1.0F, 0.0F, 1.0F}));
    square->colours.assign(3, LinearRgb{1, 0, 0});
    scene.objects.push_back({square, glm::mat4(1.0F), raster::LinearMaterial{}, raster::ShadingMethod::unlit});
    Framebuffer image(9, 9);
    raster::DepthBuffer depth;
    EXPECT_THROW(raster::render(image, scene, depth), std::invalid_argument);
}
