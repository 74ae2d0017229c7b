// `render` as a user runs it: stills, turntables, options and bad models.
#include <raster/io/obj_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/samples.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <numbers>

using raster::Framebuffer;
using test_support::kRender;
using test_support::run;
using test_support::ScratchDir;

namespace {

Framebuffer rendered(const std::filesystem::path& obj, const raster::ModelView& view, int width, int height,
                     double turn = 0.0) {
    Framebuffer image(width, height);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const raster::Model>(raster::read_obj(obj)), view, width, height)
        .render(image, depth, turn, {.samples = raster::kSmoothSamples});
    return image;
}

}  // namespace

TEST(RenderApp, AStillNamedAfterTheModelWithOneReportLine) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    const auto result = run(kRender, {"crate.obj", "--width", "200", "--height", "150"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("Wrote crate.webp: 200x150 still, ", 0), 0U) << result.out;
    EXPECT_NE(result.out.find(", 14 triangles, "), std::string::npos) << result.out;
    EXPECT_EQ(result.out.back(), '\n');
    EXPECT_EQ(result.out.find('\n'), result.out.size() - 1) << result.out;
    EXPECT_EQ(raster::read_webp(dir / "crate.webp").frames.at(0).image, rendered(obj, {}, 200, 150));
}

TEST(RenderApp, ATurntableTurnsOnceAboutUp) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    const auto result = run(
        kRender, {"crate.obj", "--turntable", "8", "--width", "64", "--height", "48", "--effort", "fast", "spin.webp"},
        dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedWebp clip = raster::read_webp(dir / "spin.webp");
    ASSERT_EQ(clip.frames.size(), 8U);
    for (const int i : {0, 3}) {
        EXPECT_EQ(clip.frames[static_cast<std::size_t>(i)].image,
                  rendered(obj, {}, 64, 48, 2.0 * std::numbers::pi * i / 8))
            << i;
    }
    EXPECT_NE(clip.frames[0].image, clip.frames[1].image);
}

TEST(RenderApp, ViewOptionsAreTheLibrarysModelView) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    const auto result =
        run(kRender, {"crate.obj", "--eye",        "3,4,5",   "--target", "0,-1,0", "--up",      "0,1,0", "--fov",
                      "50",        "--near",       "1",       "--far",    "20",     "--shading", "flat",  "--light",
                      "1,1,0",     "--background", "#102030", "--width",  "80",     "--height",  "60",    "v.webp"},
            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    raster::ModelView view;
    view.eye = glm::dvec3(3, 4, 5);
    view.target = glm::dvec3(0, -1, 0);
    view.fov_degrees = 50;
    view.near = 1;
    view.far = 20;
    view.shading = raster::ShadingMethod::flat;
    view.light = glm::dvec3(1, 1, 0);
    view.background = {0x10, 0x20, 0x30};
    EXPECT_EQ(raster::read_webp(dir / "v.webp").frames.at(0).image, rendered(obj, view, 80, 60));
}

TEST(RenderApp, UnlitOrthographicShowsTheTexturesOwnColours) {
    const ScratchDir dir;
    test_support::write_png(dir / "plain.png", test_support::checkerboard(1, 4, {200, 30, 90}, {200, 30, 90}));
    test_support::write_text(dir / "box.obj", test_support::textured_cube_obj("", ""));
    const auto result = run(kRender,
                            {"box.obj", "--texture", "plain.png", "--shading", "unlit", "--ortho", "--eye", "0,0,5",
                             "--width", "41", "--height", "41", "box.webp"},
                            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const Framebuffer image = raster::read_webp(dir / "box.webp").frames.at(0).image;
    // A map given to a model without materials shows as it is, not dimmed by the default grey.
    EXPECT_EQ(image.pixel(20, 20), (raster::Rgb{200, 30, 90}));
}

TEST(RenderApp, BadModelsAndOptionsFailWithOneLine) {
    const ScratchDir dir;
    test_support::write_text(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
    test_support::write_text(dir / "empty.obj", "");
    test_support::write_text(dir / "ok.obj", test_support::textured_cube_obj("", ""));
    std::filesystem::create_directory(dir / "folder.obj");
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"bad.obj"}, "render: bad.obj:3: face names vertex 7, but 2 are defined before it\n"},
        {{"ok.obj", "--near", "5", "--far", "1"}, "render: --near must be less than --far, got 5 and 1\n"},
        {{"ok.obj", "--ortho", "--near", "1"},
         "render: --near and --far set a perspective lens; an orthographic view draws the whole model\n"},
        {{"empty.obj"}, "render: empty.obj: nothing to draw: no faces, points or lines\n"},
        {{"folder.obj"}, "render: folder.obj: is a directory, not a file\n"},
        {{"ok.obj", "--texture", "nowhere.png"}, "render: nowhere.png: does not exist\n"},
        {{"ok.obj", "--eye", "0,5,0"}, "render: the view runs along the up direction; give another --up or --eye\n"},
    };
    for (const auto& [arguments, message] : cases) {
        const auto result = run(kRender, arguments, dir.path());
        EXPECT_EQ(result.exit_code, 1) << arguments[0];
        EXPECT_EQ(result.err, message);
    }
    for (const std::vector<std::string>& usage : {std::vector<std::string>{},
                                                  {"ok.obj", "--eye", "1,2"},
                                                  {"ok.obj", "--background", "blue"},
                                                  {"ok.obj", "--shading", "toon"},
                                                  {"ok.obj", "--fov", "180"}}) {
        const auto result = run(kRender, usage, dir.path());
        EXPECT_EQ(result.exit_code, 2) << ::testing::PrintToString(usage);
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    }
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"bad.obj", "empty.obj", "folder.obj", "ok.obj"}));
}

TEST(RenderApp, EveryPointOptionWorksBeforeBetweenAndAfterThePositionalsInEitherForm) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    const std::vector<std::pair<std::string, std::string>> points{
        {"--eye", "-3,2.5,-4"}, {"--target", "0,-0.5,0"}, {"--up", "0,1,-0.1"}, {"--light", "-1,1,-0.5"}};
    const std::vector<std::string> size{"--width", "24", "--height", "18", "--effort", "fast"};
    std::vector<std::string> reference{"crate.obj", "reference.webp"};
    for (const auto& [name, value] : points) reference.insert(reference.end(), {name, value});
    reference.insert(reference.end(), size.begin(), size.end());
    ASSERT_EQ(run(kRender, reference, dir.path()).exit_code, 0);
    const Framebuffer expected = raster::read_webp(dir / "reference.webp").frames.at(0).image;
    int case_number = 0;
    for (const auto& [name, value] : points) {
        for (int position = 0; position < 3; ++position) {
            for (const bool joined : {false, true}) {
                const std::string output = "case" + std::to_string(case_number++) + ".webp";
                const std::vector<std::string> option =
                    joined ? std::vector<std::string>{name + "=" + value} : std::vector<std::string>{name, value};
                std::vector<std::string> arguments = size;
                // The one under test before the model, between model and output, or after the output.
                const std::vector<std::string> positionals{"crate.obj", output};
                for (int slot = 0; slot <= 2; ++slot) {
                    if (slot == position) arguments.insert(arguments.end(), option.begin(), option.end());
                    if (slot < 2) arguments.push_back(positionals[static_cast<std::size_t>(slot)]);
                }
                for (const auto& [other, other_value] : points) {
                    if (other != name) arguments.insert(arguments.end(), {other + "=" + other_value});
                }
                const auto result = run(kRender, arguments, dir.path());
                ASSERT_EQ(result.exit_code, 0) << ::testing::PrintToString(arguments) << result.err;
                EXPECT_EQ(raster::read_webp(dir / output).frames.at(0).image, expected)
                    << ::testing::PrintToString(arguments);
            }
        }
    }
}
