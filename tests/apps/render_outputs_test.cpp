// `render`'s outputs: WebP or PNG, opaque or transparent, one animation or numbered frames.
#include <raster/io/obj_file.hpp>
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/samples.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

using raster::Framebuffer;
using test_support::kRender;
using test_support::run;
using test_support::ScratchDir;

namespace {

raster::DecodedPng read_png(const std::filesystem::path& path) {
    return raster::decode_png(test_support::read_bytes(path), 1 << 20);
}

// What `render` draws of the OBJ, by default at its default samples.
Framebuffer rendered(const std::filesystem::path& obj, int width, int height, double turn = 0.0,
                     int samples = raster::kSmoothSamples) {
    Framebuffer image(width, height);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const raster::Model>(raster::read_obj(obj)), {}, width, height)
        .render(image, depth, turn, {.samples = samples});
    return image;
}

}  // namespace

TEST(RenderOutputs, APngStillIsTheWebpStillsPicture) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    auto result = run(kRender, {"crate.obj", "--width", "60", "--height", "40", "still.png"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("Wrote still.png: 60x40 still, ", 0), 0U) << result.out;
    const raster::DecodedPng png = read_png(dir / "still.png");
    EXPECT_EQ(png.image, rendered(obj, 60, 40));
    EXPECT_EQ(png.alpha, std::vector<std::uint8_t>(60 * 40, 255));
    // --format chooses the format whatever the name, and says so; the default name follows it.
    result = run(kRender, {"--format", "png", "crate.obj", "--width=60", "--height=40"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(read_png(dir / "crate.png").image, png.image);
    result = run(kRender, {"crate.obj", "odd.webp", "--format=png", "--width=60", "--height=40"}, dir.path());
    EXPECT_EQ(result.err, "render: warning: 'odd.webp' does not end in .png, but it will hold PNG data\n");
    EXPECT_EQ(read_png(dir / "odd.webp").image, png.image);
}

TEST(RenderOutputs, BackgroundNoneIsTransparentInWebpAndPng) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    for (const std::string name : {"clear.webp", "clear.png"}) {
        // One sample: a pixel is surface or background, alpha 255 or 0 (SamplesSmoothEdges... has the rest).
        const auto result = run(
            kRender, {"--background", "none", "crate.obj", name, "--width", "60", "--height", "40", "--samples", "1"},
            dir.path());
        ASSERT_EQ(result.exit_code, 0) << result.err;
        EXPECT_NE(result.out.find("60x40 still on a transparent background"), std::string::npos) << result.out;
    }
    const raster::DecodedPng png = read_png(dir / "clear.png");
    const raster::DecodedFrame webp = raster::read_webp(dir / "clear.webp").frames.at(0);
    EXPECT_EQ(webp.alpha, png.alpha);
    const Framebuffer opaque = rendered(obj, 60, 40, 0.0, 1);
    const raster::Rgb background{48, 52, 60};
    int clear = 0;
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 60; ++x) {
            const std::uint8_t alpha = png.alpha[static_cast<std::size_t>(y * 60 + x)];
            EXPECT_EQ(alpha, opaque.pixel(x, y) == background ? 0 : 255) << x << "," << y;
            if (alpha == 0) {
                ++clear;
                continue;
            }
            EXPECT_EQ(png.image.pixel(x, y), opaque.pixel(x, y));
            EXPECT_EQ(webp.image.pixel(x, y), opaque.pixel(x, y));
        }
    }
    EXPECT_GT(clear, 200);  // the corners at least
    EXPECT_EQ(png.alpha[0], 0);
}

TEST(RenderOutputs, FramesDirWritesTheTurntableAsNumberedPngFiles) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    const auto result =
        run(kRender, {"crate.obj", "--frames-dir", "out/frames", "--turntable", "3", "--width", "32", "--height", "24"},
            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("Wrote out/frames/0000.png to 0002.png: 3 PNG frames of 32x24 for 30 fps, ", 0), 0U)
        << result.out;
    const std::vector<std::string> names{"0000.png", "0001.png", "0002.png"};
    std::vector<std::string> listed;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "out/frames"))
        listed.push_back(entry.path().filename().string());
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(listed, names);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(read_png(dir / "out/frames" / names[static_cast<std::size_t>(i)]).image,
                  rendered(obj, 32, 24, 2.0 * std::numbers::pi * i / 3))
            << i;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "crate.webp"));
}

TEST(RenderOutputs, ATransparentTurntableKeepsAlphaInEveryFrame) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    const auto result = run(
        kRender, {"crate.obj", "--turntable", "3", "--background=none", "--width", "32", "--height", "24", "spin.webp"},
        dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedWebp clip = raster::read_webp(dir / "spin.webp");
    ASSERT_EQ(clip.frames.size(), 3U);
    for (const raster::DecodedFrame& frame : clip.frames) {
        EXPECT_EQ(frame.alpha.front(), 0);
        EXPECT_EQ(frame.alpha[static_cast<std::size_t>(12 * 32 + 16)], 255);
    }
}

TEST(RenderOutputs, OutputsThatCannotBeAreOneLine) {
    const ScratchDir dir;
    test_support::write_crate_on_floor(dir.path());
    auto result = run(kRender, {"crate.obj", "--turntable", "2", "spin.png"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(
        result.err,
        "render: a PNG file holds one picture: write the turntable to .webp, or to numbered PNG frames with --frames-dir "
        "DIR (see --help)\n");
    result = run(kRender, {"crate.obj", "--turntable", "2", "--output-dir", "t", "--format", "png"}, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "t"));
    result = run(kRender, {"crate.obj", "--frames-dir", "f"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err, "render: --frames-dir writes the frames of a turntable; add --turntable N (see --help)\n");
    result = run(kRender, {"crate.obj", "--turntable", "2", "--frames-dir", "f", "x.webp"}, dir.path());
    EXPECT_EQ(result.exit_code, 2) << result.err;
    test_support::write_text(dir / "file", "in the way");
    result = run(kRender, {"crate.obj", "--turntable", "2", "--frames-dir", "file"}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_EQ(result.err.rfind("render: cannot make the frames directory 'file'", 0), 0U) << result.err;
    result = run(kRender, {"crate.obj", "--background", "clear"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("'clear' is not a colour like #30343c, or none"), std::string::npos) << result.err;
    // A frame may not replace an input: the texture, named as a frame.
    test_support::write_text(dir / "tex.mtl", "newmtl crate\nmap_Kd 0000.png\n");
    EXPECT_EQ(std::filesystem::copy_file(dir / "checker.png", dir / "0000.png"), true);
    test_support::write_text(dir / "tex.obj", test_support::textured_cube_obj("tex.mtl", "crate"));
    result = run(kRender, {"tex.obj", "--turntable", "2", "--frames-dir", "."}, dir.path());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("0000.png"), std::string::npos) << result.err;
}

TEST(RenderOutputs, SamplesSmoothEdgesByDefaultInAnyOptionOrderAndOnlyStandardCountsAreTaken) {
    const ScratchDir dir;
    const auto obj = test_support::write_crate_on_floor(dir.path());
    auto result =
        run(kRender, {"--samples", "4", "crate.obj", "--width", "60", "--height", "40", "before.png"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    result = run(kRender, {"crate.obj", "after.png", "--width=60", "--height=40", "--samples=4"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const Framebuffer smooth = read_png(dir / "before.png").image;
    EXPECT_EQ(read_png(dir / "after.png").image, smooth);
    result = run(kRender, {"crate.obj", "--width=60", "--height=40", "default.png"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(read_png(dir / "default.png").image, smooth);  // four samples unless told
    // The library's picture at four samples, which differs from one sample's only along edges.
    Framebuffer expected(60, 40);
    raster::Renderer renderer({.threads = 1, .samples = 4});
    raster::ModelStage(std::make_shared<const raster::Model>(raster::read_obj(obj)), {}, 60, 40)
        .render(expected, renderer);
    EXPECT_EQ(smooth, expected);
    EXPECT_NE(smooth, rendered(obj, 60, 40, 0.0, 1));
    // A transparent background takes the share of samples covered as alpha.
    result =
        run(kRender,
            {"crate.obj", "--background", "none", "--samples", "16", "--width", "60", "--height", "40", "clear.png"},
            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedPng clear = read_png(dir / "clear.png");
    EXPECT_TRUE(std::any_of(clear.alpha.begin(), clear.alpha.end(), [](std::uint8_t a) { return a > 0 && a < 255; }));
    result = run(kRender, {"crate.obj", "--samples", "3", "x.png"}, dir.path());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_EQ(result.err, "render: --samples: '3' is not one of 1, 2, 4, 8, 16 (see --help)\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}
