// The Phase 2 shaders on the one rasterizer: what each interpolates shows in the pictures.
#include <raster/geometry/shapes.hpp>
#include <raster/rasterize/draw_mesh.hpp>
#include <raster/render/scene.hpp>

#include <memory>
#include <numbers>
#include <string>
#include <vector>
#include <glm/ext/matrix_transform.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

// A 2 x 2 square facing the camera, filling a 9 x 9 image, lit only by a lamp 0.3 in front of
// its centre: two facets, four corners.
raster::Scene lamp_over_square(raster::ShadingMethod method) {
    raster::Scene scene{raster::OrthoCamera(9, 9), {0, 0, 0}, {}, {}, {}};
    scene.point_lights = {{{0.0F, 0.0F, -0.3F}, 1.0F, raster::Falloff{}}};
    const auto square = std::make_shared<const raster::Mesh>(
        raster::ground_quad({-1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, 1.0F}, {-1.0F, 0.0F, 1.0F}));
    const glm::mat4 facing_camera = glm::rotate(glm::mat4(1.0F), -std::numbers::pi_v<float> / 2, {1.0F, 0.0F, 0.0F});
    scene.objects.push_back(
        {square, facing_camera, raster::LinearMaterial{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {}}, method});
    return scene;
}

// Grey levels as characters: '#' 230 and up, 'o' 160, '-' 100, ':' 1, '.' black.
std::vector<std::string> levels(const Framebuffer& image) {
    std::vector<std::string> rows;
    for (int y = 0; y < image.height(); ++y) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) {
            const int v = image.pixel(x, y).r;
            row += v >= 230 ? '#' : v >= 160 ? 'o' : v >= 100 ? '-' : v >= 1 ? ':' : '.';
        }
        rows.push_back(row);
    }
    return rows;
}

std::vector<std::string> render(raster::ShadingMethod method) {
    Framebuffer image(9, 9);
    raster::DepthBuffer depth;
    raster::render(image, lamp_over_square(method), depth);
    return levels(image);
}

}  // namespace

// Phong interpolates the world position, so a lamp close to a large facet lights a spot in its
// middle; Gouraud lights the four far corners only and spreads their dim colour across.
TEST(LinearShaders, PhongSeesAPointLightBetweenTheCornersGouraudDoesNot) {
    // The square's right and bottom edges run through pixel centres: the fill rule leaves them out.
    EXPECT_EQ(render(raster::ShadingMethod::phong), (std::vector<std::string>{
                                                        "--------.",
                                                        "---ooo--.",
                                                        "--ooooo-.",
                                                        "-ooooooo.",
                                                        "-ooo#ooo.",
                                                        "-ooooooo.",
                                                        "--ooooo-.",
                                                        "---ooo--.",
                                                        ".........",
                                                    }));
    std::vector<std::string> uniform(8, "--------.");
    uniform.emplace_back(".........");
    EXPECT_EQ(render(raster::ShadingMethod::gouraud), uniform);
    // Flat shading lights each facet once, at its centroid, nearer the lamp than any corner.
    std::vector<std::string> flat(8, "oooooooo.");
    flat.emplace_back(".........");
    EXPECT_EQ(render(raster::ShadingMethod::flat), flat);
}

// The pixel write encodes linear light to sRGB exactly: a lamp giving linear 0.5 writes 188.
TEST(LinearShaders, ThePixelWriteEncodesLinearLightToSrgb) {
    raster::Scene scene = lamp_over_square(raster::ShadingMethod::gouraud);
    scene.point_lights.clear();
    scene.lights = {{{0.0F, 0.0F, -1.0F}, 0.5F}};
    Framebuffer image(9, 9);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth);
    EXPECT_EQ(image.pixel(4, 4), (raster::Rgb{188, 188, 188}));
    EXPECT_EQ(raster::srgb_byte_from_linear(0.5F), 188);
}
