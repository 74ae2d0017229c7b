// still-scene and animated-scene as a user runs them.
#include <raster/io/webp.hpp>
#include <raster/render/render_style.hpp>
#include <raster/render/samples.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include "support/scratch.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using raster::Framebuffer;
using test_support::kAnimatedScene;
using test_support::kStillScene;
using test_support::run;
using test_support::ScratchDir;

namespace {

Framebuffer still_of(std::string_view name, int width, int height) {
    Framebuffer image(width, height);
    raster::DepthBuffer depth;
    raster::render(image, raster::DiaryScene(name).still(width, height), depth);
    return image;
}

}  // namespace

TEST(StillSceneApp, WritesTheOriginalsFinalSceneByDefault) {
    const ScratchDir dir;
    const auto result = run(kStillScene, {}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out.rfind("Wrote still-scene.webp: 800x600 still, ", 0), 0U) << result.out;
    EXPECT_EQ(raster::read_webp(dir / "still-scene.webp").frames.at(0).image, still_of("point-lights", 800, 600));
}

TEST(StillSceneApp, EverySceneAtAnySizeDecodesToTheInMemoryRender) {
    const ScratchDir dir;
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        const std::string name(info.name);
        const auto result =
            run(kStillScene, {"--scene", name, "--width", "120", "--height", "90", "--effort", "fast", "s.webp"},
                dir.path());
        ASSERT_EQ(result.exit_code, 0) << name << ": " << result.err;
        EXPECT_EQ(raster::read_webp(dir / "s.webp").frames.at(0).image, still_of(info.name, 120, 90)) << name;
    }
}

TEST(StillSceneApp, PerspectiveLooksThroughAPinholeKeepingTheFraming) {
    const ScratchDir dir;
    const auto result =
        run(kStillScene, {"--scene", "point-light", "--perspective", "50", "--width", "96", "--height", "72", "p.webp"},
            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    Framebuffer expected(96, 72);
    raster::DepthBuffer depth;
    raster::render(expected, raster::in_perspective(raster::DiaryScene("point-light").still(96, 72), 96, 72, 50.0),
                   depth);
    const Framebuffer written = raster::read_webp(dir / "p.webp").frames.at(0).image;
    EXPECT_EQ(written, expected);
    EXPECT_NE(written, still_of("point-light", 96, 72));
}

TEST(StillSceneApp, SamplesDrawTheSceneAtEachSamplePositionDiaryAndSeedAlike) {
    const ScratchDir dir;
    auto result = run(kStillScene, {"--scene", "torus", "--samples", "4", "--width", "96", "--height", "72", "t.webp"},
                      dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    Framebuffer expected(96, 72);
    raster::DepthBuffer depth;
    raster::render(expected, raster::DiaryScene("torus").still(96, 72), depth, {.samples = 4});
    const Framebuffer written = raster::read_webp(dir / "t.webp").frames.at(0).image;
    EXPECT_EQ(written, expected);
    EXPECT_NE(written, still_of("torus", 96, 72));
    result =
        run(kAnimatedScene,
            {"--scene=ptah", "--frames", "2", "--samples=2", "--width", "64", "--height", "48", "p.webp"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(raster::read_webp(dir / "p.webp").frames.size(), 2U);
}

TEST(AnimatedSceneApp, WritesTheScenesOwnFrameCountTwentyMillisecondsApart) {
    const ScratchDir dir;
    const auto result =
        run(kAnimatedScene, {"--scene", "orbit", "--width", "64", "--height", "48", "--effort", "fast"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("Wrote animated-scene.webp: 64x48, 720 frames, 14400 ms"), std::string::npos)
        << result.out;
    const raster::DecodedWebp decoded = raster::read_webp(dir / "animated-scene.webp");
    const raster::DiaryScene orbit("orbit");
    Framebuffer expected(64, 48);
    raster::DepthBuffer depth;
    int shown = 0;
    for (const raster::DecodedFrame& frame : decoded.frames) {
        ASSERT_EQ(frame.start_ms, shown * 20);
        raster::render(expected, orbit.frame(64, 48, shown, 720), depth);
        ASSERT_EQ(frame.image, expected) << "frame " << shown;
        shown += frame.duration_ms / 20;  // libwebp merges identical neighbours
    }
    EXPECT_EQ(shown, 720);
}

TEST(AnimatedSceneApp, HonoursFramesAndFps) {
    const ScratchDir dir;
    const auto result =
        run(kAnimatedScene, {"--frames", "6", "--fps", "10", "--width", "80", "--height", "60", "t.webp"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedWebp decoded = raster::read_webp(dir / "t.webp");
    ASSERT_EQ(decoded.frames.size(), 6U);
    const raster::DiaryScene final_scene("point-lights");  // the default
    Framebuffer expected(80, 60);
    raster::DepthBuffer depth;
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(decoded.frames[static_cast<std::size_t>(i)].start_ms, i * 100);
        raster::render(expected, final_scene.frame(80, 60, i, 6), depth);
        EXPECT_EQ(decoded.frames[static_cast<std::size_t>(i)].image, expected) << "frame " << i;
    }
}

TEST(SceneApps, HelpListsEverySceneWithTheReleaseItReCreates) {
    const ScratchDir dir;
    for (const std::string& app : {kStillScene, kAnimatedScene}) {
        const auto result = run(app, {"--help"}, dir.path());
        EXPECT_EQ(result.exit_code, 0);
        for (const raster::SceneInfo& info : raster::diary_scenes()) {
            const std::string line = "  " + std::string(info.name);
            const std::size_t at = result.out.find(line + " ");
            ASSERT_NE(at, std::string::npos) << app << " lacks " << info.name;
            EXPECT_NE(result.out.substr(at, 60).find(info.release), std::string::npos) << info.name;
        }
        EXPECT_NE(result.out.find("--scene NAME [point-lights]"), std::string::npos) << result.out;
        EXPECT_NE(result.out.find("The default, point-lights, is also the original's final animation"),
                  std::string::npos)
            << result.out;
    }
}

TEST(CubeApps, LitStyleIsTheDiarysLitCube) {
    const ScratchDir dir;
    const auto result =
        run(test_support::kStillCube, {"--style", "lit", "--width", "100", "--height", "80", "lit.webp"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    Framebuffer expected(100, 80);
    raster::render_still_cube(expected, raster::CubeStyle::lit);
    EXPECT_EQ(raster::read_webp(dir / "lit.webp").frames.at(0).image, expected);
    EXPECT_EQ(expected, still_of("lit-cube", 100, 80));
}

TEST(StillSceneApp, TheSeedScenesRenderInTheirOwnCamerasAndRefuseDiaryOptions) {
    const ScratchDir dir;
    const auto result =
        run(kStillScene, {"--scene", "ptah", "--width", "160", "--height", "120", "p.webp"}, dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    Framebuffer expected(160, 120);
    raster::DepthBuffer depth;
    raster::render(expected, raster::SeedScene("ptah").still(160, 120), depth, {.samples = raster::kSmoothSamples});
    EXPECT_EQ(raster::read_webp(dir / "p.webp").frames.at(0).image, expected);
    const auto perspective = run(kStillScene, {"--scene", "ptah", "--perspective", "40", "q.webp"}, dir.path());
    EXPECT_EQ(perspective.exit_code, 1);
    EXPECT_EQ(perspective.err, "still-scene: --perspective applies to the diary's scenes; ptah has its own camera\n");
    const auto detail = run(kAnimatedScene, {"--scene", "flythrough", "--detail", "auto", "r.webp"}, dir.path());
    EXPECT_EQ(detail.exit_code, 1);
    const auto help = run(kStillScene, {"--help"}, dir.path());
    EXPECT_NE(help.out.find("flythrough      raster-engine: "), std::string::npos) << help.out;
}

TEST(AnimatedSceneApp, TheFlightIsAnAnimationOfItsOwnFrames) {
    const ScratchDir dir;
    const auto result =
        run(kAnimatedScene,
            {"--scene", "flythrough", "--frames", "4", "--width", "64", "--height", "48", "--effort", "fast", "f.webp"},
            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedWebp clip = raster::read_webp(dir / "f.webp");
    ASSERT_EQ(clip.frames.size(), 4U);
    Framebuffer expected(64, 48);
    raster::DepthBuffer depth;
    raster::render(expected, raster::SeedScene("flythrough").frame(64, 48, 2, 4), depth,
                   {.samples = raster::kSmoothSamples});
    EXPECT_EQ(clip.frames[2].image, expected);
}

TEST(StillSceneApp, AViewFramesOneElementOfTheIslandsInAnyStyle) {
    const ScratchDir dir;
    const auto result =
        run(kStillScene, {"--width=64", "falls.webp", "--view", "waterfall", "--height", "48", "--effort", "fast"},
            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::SeedScene islands("islands");
    Framebuffer expected(64, 48);
    raster::DepthBuffer depth;
    raster::render(expected, islands.view("waterfall", 64, 48), depth, {.samples = raster::kSmoothSamples});
    EXPECT_EQ(raster::read_webp(dir / "falls.webp").frames.at(0).image, expected);

    const auto wire =
        run(kStillScene, {"--scene", "islands", "w.webp", "--style=wireframe", "--width", "64", "--height", "48"},
            dir.path());
    ASSERT_EQ(wire.exit_code, 0) << wire.err;
    Framebuffer lines(64, 48);
    raster::draw_wireframe(lines, islands.still(64, 48));
    EXPECT_EQ(raster::read_webp(dir / "w.webp").frames.at(0).image, lines);

    const auto other = run(kStillScene, {"--scene", "ptah", "--view", "boat", "x.webp"}, dir.path());
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_EQ(other.err, "still-scene: --view frames an element of the islands; ptah has none\n");
    const auto unknown = run(kStillScene, {"--view", "volcano", "x.webp"}, dir.path());
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_NE(unknown.err.find("parked-plane"), std::string::npos) << unknown.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.webp"));
    const auto style = run(kAnimatedScene, {"--style", "cel", "x.webp"}, dir.path());
    EXPECT_EQ(style.exit_code, 2);
    EXPECT_NE(style.err.find("wireframe"), std::string::npos) << style.err;
}

TEST(AnimatedSceneApp, TheIslandsFlyInFlatStyleFrameForFrame) {
    const ScratchDir dir;
    const auto result = run(kAnimatedScene,
                            {"i.webp", "--scene", "islands", "--frames", "3", "--style", "flat", "--width", "48",
                             "--height", "36", "--effort", "fast"},
                            dir.path());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const raster::DecodedWebp clip = raster::read_webp(dir / "i.webp");
    ASSERT_EQ(clip.frames.size(), 3U);
    Framebuffer expected(48, 36);
    raster::DepthBuffer depth;
    raster::render(expected, raster::flat_style(raster::SeedScene("islands").frame(48, 36, 1, 3)), depth,
                   {.samples = raster::kSmoothSamples});
    EXPECT_EQ(clip.frames[1].image, expected);
}
