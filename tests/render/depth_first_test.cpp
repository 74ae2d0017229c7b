// Depth first: every object's depth before any colour gives the same picture as one pass.
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include "render/depth_first.hpp"

#include <string>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::RenderOptions;

namespace {

constexpr int kWidth = 160, kHeight = 120;

// One sample, multisampled, supersampled and on three threads; the picture and, for a scene that
// keeps depth, the coverage a Renderer hands out as alpha.
template <typename Scene>
void expect_same_either_way(const Scene& scene, const std::string& name) {
    const RenderOptions ways[] = {
        {.samples = 1}, {.samples = 4}, {.samples = 2, .shade_every_sample = true}, {.threads = 3, .samples = 4}};
    for (RenderOptions options : ways) {
        Framebuffer one_pass(kWidth, kHeight), depth_first(kWidth, kHeight);
        options.depth_first = RenderOptions::DepthFirst::never;
        raster::Renderer plain(options);
        plain.render(one_pass, scene);
        options.depth_first = RenderOptions::DepthFirst::always;
        raster::Renderer first(options);
        first.render(depth_first, scene);
        EXPECT_EQ(one_pass, depth_first) << name << " at " << options.samples << " samples, threads "
                                         << options.threads;
        EXPECT_EQ(plain.coverage(), first.coverage()) << name << " at " << options.samples << " samples";
    }
}

}  // namespace

TEST(DepthFirst, EveryDiaryAndSeedSceneLooksTheSameDrawnDepthFirst) {
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        const raster::DiaryScene scene(info.name);
        expect_same_either_way(scene.still(kWidth, kHeight), std::string(info.name));
        expect_same_either_way(scene.frame(kWidth, kHeight, info.frames / 3, info.frames),
                               std::string(info.name) + " frame");
        raster::Scene transparent = scene.still(kWidth, kHeight);
        transparent.keep_depth = true;  // the coverage becomes the alpha of a transparent picture
        expect_same_either_way(transparent, std::string(info.name) + " kept depth");
    }
    for (const raster::SeedSceneInfo& info : raster::seed_scenes()) {
        const raster::SeedScene scene(info.name);
        expect_same_either_way(scene.still(kWidth, kHeight), std::string(info.name));
        expect_same_either_way(scene.frame(kWidth, kHeight, info.frames / 3, info.frames),
                               std::string(info.name) + " frame");
    }
}

TEST(DepthFirst, ChosenForOverlappingObjectsLitPerPixelOnly) {
    const auto chosen = [](const auto& scene) { return raster::detail::depth_first(scene, true, 320, 240); };
    EXPECT_TRUE(chosen(raster::SeedScene("flythrough").still(320, 240)));  // sea, sand and grass under every pixel
    EXPECT_FALSE(chosen(raster::SeedScene("ptah").still(320, 240)));       // one object
    EXPECT_FALSE(chosen(raster::DiaryScene("shaders").still(320, 240)));   // two tori side by side
    raster::PerspectiveScene flat = raster::SeedScene("flythrough").still(320, 240);
    for (raster::SceneObject& object : flat.objects)
        object.shading = raster::ShadingMethod::flat, object.texture = nullptr;
    EXPECT_FALSE(chosen(flat));  // cheap to shade: a second pass would cost more than it saves
}
