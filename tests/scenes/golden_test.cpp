// One table of golden pictures; stays whole so that every pinned output is listed in one place.
#include <raster/io/webp.hpp>
#include <raster/render/samples.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/scenes.hpp>

#include <raster/io/obj_file.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/render_style.hpp>
#include <raster/scenes/island_world.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include "support/golden.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

using raster::CubeStyle;
using raster::Framebuffer;
using test_support::matches_snapshot;

namespace {

Framebuffer scene_frame() { return {raster::kSceneWidth, raster::kSceneHeight}; }

std::string style_name(CubeStyle style) {
    switch (style) {
    case CubeStyle::filled: return "filled";
    case CubeStyle::wireframe: return "wireframe";
    case CubeStyle::culled_wireframe: return "culled-wireframe";
    case CubeStyle::lit: return "lit";
    }
    return "unknown";
}

}  // namespace

TEST(Golden, WhitePixelAtTheCentre) {
    Framebuffer image = scene_frame();
    raster::render_white_pixel(image);
    EXPECT_TRUE(matches_snapshot(image, "white-pixel"));
}

TEST(Golden, RadialSpokes) {
    Framebuffer image = scene_frame();
    raster::render_spokes(image);
    EXPECT_TRUE(matches_snapshot(image, "spokes"));
}

TEST(Golden, StillCubeInEachStyle) {
    for (const CubeStyle style :
         {CubeStyle::filled, CubeStyle::wireframe, CubeStyle::culled_wireframe, CubeStyle::lit}) {
        Framebuffer image = scene_frame();
        raster::render_still_cube(image, style);
        EXPECT_TRUE(matches_snapshot(image, "still-cube/" + style_name(style)));
    }
}

TEST(Golden, StillUnitCube) {
    Framebuffer image = scene_frame();
    raster::render_unit_cube(image);
    EXPECT_TRUE(matches_snapshot(image, "still-unit-cube"));
}

TEST(Golden, AnimatedCubeEveryThirtiethFrame) {
    for (int frame = 0; frame < raster::kAnimationFrameCount; frame += 30) {
        Framebuffer image = scene_frame();
        raster::render_tumble_frame(image, frame, raster::kAnimationFrameCount, CubeStyle::filled);
        char name[32];
        std::snprintf(name, sizeof name, "animated-cube/frame-%03d", frame);
        EXPECT_TRUE(matches_snapshot(image, name));
    }
}

TEST(Golden, AnimatedCubeDigestOfEveryFrameInEachStyle) {
    for (const CubeStyle style : {CubeStyle::filled, CubeStyle::wireframe, CubeStyle::culled_wireframe}) {
        std::vector<std::string> digests;
        Framebuffer image = scene_frame();
        for (int frame = 0; frame < raster::kAnimationFrameCount; ++frame) {
            raster::render_tumble_frame(image, frame, raster::kAnimationFrameCount, style);
            digests.push_back(test_support::digest_of(image));
        }
        EXPECT_TRUE(test_support::matches_digests(digests, "animated-cube/" + style_name(style)));
    }
}

TEST(Golden, ReadmeAnimationsShowWhatTheExporterDrawsToday) {
    if (std::getenv("RASTER_UPDATE_SNAPSHOTS") != nullptr) GTEST_SKIP() << "update-snapshots rewrites them next";
    for (const CubeStyle style : {CubeStyle::filled, CubeStyle::wireframe, CubeStyle::culled_wireframe}) {
        const std::string file = style == CubeStyle::filled ? "animated-cube" : "animated-" + style_name(style);
        std::vector<std::string> digests;
        raster::for_each_webp_frame(std::string(RASTER_IMAGES_DIR) + "/" + file + ".webp",
                                    [&](const raster::DecodedFrame& frame) {
                                        // libwebp merges identical neighbours into one longer frame
                                        const int shown = frame.duration_ms / raster::kFrameSpacingMs;
                                        for (int i = 0; i < shown; ++i)
                                            digests.push_back(test_support::digest_of(frame.image));
                                        return true;
                                    });
        EXPECT_TRUE(test_support::matches_digests(digests, "animated-cube/" + style_name(style)))
            << "doc/images/" << file << ".webp is stale: cmake --build --preset release --target update-snapshots";
    }
}

TEST(Golden, EveryDiaryScenesStill) {
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        Framebuffer image = scene_frame();
        raster::DepthBuffer depth;
        raster::render(image, raster::DiaryScene(info.name).still(image.width(), image.height()), depth);
        EXPECT_TRUE(matches_snapshot(image, "scenes/" + std::string(info.name)));
    }
}

// The same stills through a 60-degree pinhole (--perspective 60): near-plane clipping, 1/w
// interpolation and per-point view directions, pinned.
TEST(Golden, DiaryStillsInPerspective) {
    for (const std::string_view name : {"two-spheres", "point-light", "shaders"}) {
        Framebuffer image = scene_frame();
        raster::DepthBuffer depth;
        const raster::Scene scene = raster::DiaryScene(name).still(image.width(), image.height());
        raster::render(image, raster::in_perspective(scene, image.width(), image.height(), 60.0), depth);
        EXPECT_TRUE(matches_snapshot(image, "perspective/" + std::string(name)));
    }
}

TEST(Golden, EveryDiaryScenesAnimationEveryTenthFrame) {
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        const raster::DiaryScene scene(info.name);
        std::vector<std::string> digests;
        Framebuffer image = scene_frame();
        raster::DepthBuffer depth;
        for (int frame = 0; frame < info.frames; frame += 10) {
            raster::render(image, scene.frame(image.width(), image.height(), frame, info.frames), depth);
            digests.push_back(test_support::digest_of(image));
        }
        EXPECT_TRUE(test_support::matches_digests(digests, "scenes/" + std::string(info.name)));
    }
}

TEST(Golden, ReadmeTorusIsWhatAnimatedSceneDrawsToday) {
    if (std::getenv("RASTER_UPDATE_SNAPSHOTS") != nullptr) GTEST_SKIP() << "update-snapshots rewrites it next";
    const raster::DiaryScene torus("point-lights");  // the diary's last look: Phase 2's torus
    Framebuffer expected(320, 240);                  // as update-snapshots renders it: 180 frames at 25 fps
    raster::DepthBuffer depth;
    int shown = 0;
    raster::for_each_webp_frame(
        std::string(RASTER_IMAGES_DIR) + "/animated-scene.webp", [&](const raster::DecodedFrame& frame) {
            raster::render(expected, torus.frame(320, 240, shown, 180), depth);
            EXPECT_EQ(frame.image, expected) << "doc/images/animated-scene.webp is stale at frame " << shown
                                             << ": cmake --build --preset release --target update-snapshots";
            shown += frame.duration_ms / 40;  // libwebp merges identical neighbours
            return frame.image == expected;
        });
    EXPECT_EQ(shown, 180);
}

// What `render` draws of a model it reads, at its default samples: a textured crate on a floor,
// each shading, the orthographic view, a turntable frame, a low eye, nearest filtering, and one sample.
TEST(Golden, ModelsThroughEachShadingAndView) {
    const test_support::ScratchDir dir;
    const auto model =
        std::make_shared<const raster::Model>(raster::read_obj(test_support::write_crate_on_floor(dir.path())));
    struct Case {
        std::string name;
        raster::ModelView view;
        double turn = 0.0;
        int samples = raster::kSmoothSamples;
    };
    std::vector<Case> cases;
    for (const auto& [name, shading] :
         {std::pair{"phong", raster::ShadingMethod::phong}, std::pair{"gouraud", raster::ShadingMethod::gouraud},
          std::pair{"flat", raster::ShadingMethod::flat}, std::pair{"unlit", raster::ShadingMethod::unlit}}) {
        raster::ModelView view;
        view.shading = shading;
        cases.push_back({name, view});
    }
    raster::ModelView ortho;
    ortho.orthographic = true;
    cases.push_back({"ortho", ortho});
    cases.push_back({"turned", raster::ModelView{}, 0.25 * 3.14159265358979});
    raster::ModelView low;
    low.eye = glm::dvec3(0.0, -0.6, 5.0);
    low.fov_degrees = 60.0;
    cases.push_back({"low-eye", low});
    cases.push_back({"nearest", raster::ModelView{}});
    cases.push_back({"one-sample", raster::ModelView{}, 0.0, 1});
    for (const Case& c : cases) {
        Framebuffer image(160, 120);
        raster::DepthBuffer depth;
        auto copy = std::make_shared<raster::Model>(*model);
        if (c.name == "nearest") {
            for (raster::ModelPart& part : copy->parts) part.sampler.filter = raster::TextureFilter::nearest;
        }
        raster::ModelStage(copy, c.view, image.width(), image.height())
            .render(image, depth, c.turn, {.samples = c.samples});
        EXPECT_TRUE(matches_snapshot(image, "models/crate-" + c.name));
    }
}

// Faces of many corners as CAD and LightWave exports write them, each one face: a ring cut open
// by a slit (66 corners), a star and a comb, drawn exactly as their outlines.
TEST(Golden, ConcaveFacesAsTheirOutlines) {
    std::string obj;
    std::size_t next = 1;
    const auto face = [&](const std::vector<std::pair<double, double>>& outline, double dx, double dy) {
        std::string corners = "f";
        for (const auto& [x, y] : outline) {
            obj += "v " + std::to_string(x + dx) + " " + std::to_string(y + dy) + " 0\n";
            corners += " " + std::to_string(next++);
        }
        obj += corners + "\n";
    };
    const double pi = 3.14159265358979;
    std::vector<std::pair<double, double>> ring;
    for (int i = 0; i <= 32; ++i) ring.emplace_back(std::cos(2 * pi * i / 32), std::sin(2 * pi * i / 32));
    for (int i = 0; i <= 32; ++i)
        ring.emplace_back(0.55 * std::cos(-2 * pi * i / 32), 0.55 * std::sin(-2 * pi * i / 32));
    std::vector<std::pair<double, double>> star;
    for (int i = 0; i < 10; ++i)
        star.emplace_back((i % 2 == 0 ? 1.0 : 0.4) * -std::sin(pi * i / 5),
                          (i % 2 == 0 ? 1.0 : 0.4) * std::cos(pi * i / 5));
    std::vector<std::pair<double, double>> comb{{-1, -1}, {1, -1}};  // counter-clockwise, as OBJ's fronts are
    for (int tooth = 4; tooth >= 0; --tooth) {
        const double left = -1 + 0.45 * tooth, right = left + 0.2;
        if (tooth < 4) comb.emplace_back(right, -0.4);
        comb.emplace_back(right, 1);
        comb.emplace_back(left, 1);
        if (tooth > 0) comb.emplace_back(left, -0.4);
    }
    face(ring, -1.1, 1.1);
    face(star, 1.1, 1.1);
    face(comb, 0.0, -1.1);
    raster::ModelView view;
    view.orthographic = true;
    view.eye = glm::dvec3(0.0, 0.0, 5.0);
    view.shading = raster::ShadingMethod::unlit;
    Framebuffer image(160, 160);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<raster::Model>(raster::parse_obj(obj, "")), view, image.width(), image.height())
        .render(image, depth, 0.0);
    EXPECT_TRUE(matches_snapshot(image, "models/concave-faces"));
}

// The Ptah and raster-engine scenes at their default samples: stills, and the flight every hundredth frame.
TEST(Golden, SeedScenes) {
    for (const raster::SeedSceneInfo& info : raster::seed_scenes()) {
        Framebuffer image(320, 240);
        raster::DepthBuffer depth;
        const raster::SeedScene scene(info.name);
        raster::render(image, scene.still(image.width(), image.height()), depth, {.samples = raster::kSmoothSamples});
        EXPECT_TRUE(matches_snapshot(image, "seeds/" + std::string(info.name)));
    }
    const raster::SeedScene fly("flythrough");
    for (const int i : {100, 200, 300}) {
        Framebuffer image(160, 120);
        raster::DepthBuffer depth;
        raster::render(image, fly.frame(image.width(), image.height(), i, fly.info().frames), depth,
                       {.samples = raster::kSmoothSamples});
        EXPECT_TRUE(matches_snapshot(image, "seeds/flythrough-" + std::to_string(i)));
    }
}

// raster-engine's whole world: a still framed on each element, three frames of the flight (the
// canyon, over the strait, down the runway), and its flat and wireframe render modes.
TEST(Golden, IslandWorld) {
    const raster::IslandWorld world;
    for (const raster::IslandElement& element : raster::island_elements()) {
        Framebuffer image(160, 120);
        raster::DepthBuffer depth;
        raster::render(image, world.view(element.name, image.width(), image.height()), depth,
                       {.samples = raster::kSmoothSamples});
        EXPECT_TRUE(matches_snapshot(image, "islands/" + std::string(element.name)));
    }
    const raster::SeedScene islands("islands");
    for (const int i : {80, 250, 400}) {
        Framebuffer image(160, 120);
        raster::DepthBuffer depth;
        raster::render(image, islands.frame(image.width(), image.height(), i, islands.info().frames), depth,
                       {.samples = raster::kSmoothSamples});
        EXPECT_TRUE(matches_snapshot(image, "islands/flight-" + std::to_string(i)));
    }
    Framebuffer flat(160, 120), wireframe(160, 120);
    raster::DepthBuffer depth;
    raster::render(flat, raster::flat_style(islands.still(160, 120)), depth, {.samples = raster::kSmoothSamples});
    EXPECT_TRUE(matches_snapshot(flat, "islands/style-flat"));
    raster::draw_wireframe(wireframe, islands.still(160, 120));
    EXPECT_TRUE(matches_snapshot(wireframe, "islands/style-wireframe"));
}
