// Framing, near and far, and depth follow the model's size: a model drawn at a thousandth or a
// million times the size, or ten million units from the origin, gives the same picture.
#include <raster/io/obj_file.hpp>
#include <raster/render/model_scene.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

using raster::Framebuffer;

namespace {

// Two unit squares, the red one half a unit behind and beside the green one, so depth decides
// what shows where they overlap; `scale` and `offset` place both in the file's coordinates.
std::string two_squares(double scale, double offset) {
    std::string obj;
    const auto vertex = [&](double x, double y, double z) {
        char line[128];
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", offset + x * scale, offset + y * scale,
                      offset + z * scale);
        obj += line;
    };
    for (const double z : {0.0, -0.5}) {
        const double shift = z == 0.0 ? 0.0 : 0.5;
        vertex(shift, shift, z);
        vertex(shift + 1, shift, z);
        vertex(shift + 1, shift + 1, z);
        vertex(shift, shift + 1, z);
    }
    return "mtllib m.mtl\nusemtl green\n" + obj + "f 1 2 3 4\nusemtl red\nf 5 6 7 8\n";
}

Framebuffer picture_of(double scale, double offset, bool orthographic) {
    const raster::Model model =
        raster::parse_obj(two_squares(scale, offset), "newmtl green\nKd 0 1 0\nnewmtl red\nKd 1 0 0\n");
    raster::ModelView view;
    view.shading = raster::ShadingMethod::unlit;
    view.orthographic = orthographic;
    Framebuffer image(40, 30);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const raster::Model>(model), view, 40, 30).render(image, depth);
    return image;
}

std::string error_of(const std::string& obj) {
    try {
        (void)raster::parse_obj(obj, "");
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(ModelFraming, AModelAThousandthOrAMillionTimesTheSizeOrFarFromTheOriginLooksTheSame) {
    for (const bool orthographic : {false, true}) {
        const Framebuffer unit = picture_of(1.0, 0.0, orthographic);
        // Both colours show: the picture is not blank, and depth has chosen between them.
        int green = 0, red = 0;
        for (int y = 0; y < unit.height(); ++y) {
            for (int x = 0; x < unit.width(); ++x) {
                green += unit.pixel(x, y) == raster::Rgb{0, 255, 0} ? 1 : 0;
                red += unit.pixel(x, y) == raster::Rgb{255, 0, 0} ? 1 : 0;
            }
        }
        EXPECT_GT(green, 100);
        EXPECT_GT(red, 50);
        EXPECT_EQ(picture_of(0.008, 0.0, orthographic), unit) << "a quad 0.008 across";
        EXPECT_EQ(picture_of(8000.0, 0.0, orthographic), unit) << "the same a million times larger";
        EXPECT_EQ(picture_of(8000.0, 1e7, orthographic), unit) << "and ten million units from the origin";
    }
}

TEST(ModelFraming, FacesTooSmallForFloatsAtTheirDistanceAreRefusedWithTheReason) {
    // 0.008 across at 10^7: 32-bit floats there step by 1, so the square has no area left.
    EXPECT_EQ(error_of("v 1e7 1e7 1e7\nv 10000000.008 1e7 1e7\nv 10000000.008 10000000.008 1e7\nf 1 2 3\n"),
              "<memory>: every face has no area (stored as 32-bit floats, coordinates near 1e+07 step by 1: move the "
              "model nearer the origin)");
}

TEST(ModelFraming, AStageThatTakesItsModelDrawsWhatOneSharingItDraws) {
    // Open squares are drawn from both sides (copied, unless culled); the points' part moves over as it is.
    const raster::Model model = raster::parse_obj(two_squares(1.0, 0.0) + "v 0.2 0.8 0.3\nv 0.9 0.1 0.3\np 9 10\n",
                                                  "newmtl green\nKd 0 1 0\nnewmtl red\nKd 1 0 0\n");
    ASSERT_EQ(model.parts.size(), 3U);
    for (const bool orthographic : {false, true}) {
        for (const raster::Culling cull : {raster::Culling::automatic, raster::Culling::back}) {
            raster::ModelView view;
            view.orthographic = orthographic;
            view.cull = cull;  // back: every part moves over
            view.points_and_lines.point_size = 5.0;
            const auto drawn = [&](const raster::ModelStage& stage) {
                Framebuffer image(40, 30);
                raster::DepthBuffer depth;
                stage.render(image, depth, 0.7);
                return image;
            };
            const Framebuffer shared =
                drawn(raster::ModelStage(std::make_shared<const raster::Model>(model), view, 40, 30));
            raster::Model taken = model;
            EXPECT_EQ(drawn(raster::ModelStage(std::move(taken), view, 40, 30)), shared) << orthographic;
            view.shading = raster::ShadingMethod::unlit;
            EXPECT_NE(drawn(raster::ModelStage(raster::Model(model), view, 40, 30)), shared) << "the test can tell";
        }
    }
}
