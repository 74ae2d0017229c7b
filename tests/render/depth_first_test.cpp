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

template <typename Scene>
void expect_same_either_way(const Scene& scene, const std::string& name) {
    for (const int samples : {1, 4}) {
        Framebuffer one_pass(kWidth, kHeight), depth_first(kWidth, kHeight);
        raster::DepthBuffer depth;
        raster::render(one_pass, scene, depth, {.samples = samples, .depth_first = RenderOptions::DepthFirst::never});
        raster::render(depth_first, scene, depth, {.samples = samples, .depth_first = RenderOptions::DepthFirst::always});
        EXPECT_EQ(one_pass, depth_first) << name << " at " << samples << " samples";
    }
}

}  // namespace

TEST(DepthFirst, EveryDiaryAndSeedSceneLooksTheSameDrawnDepthFirst) {
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        const raster::DiaryScene scene(info.name);
        expect_same_either_way(scene.still(kWidth, kHeight), std::string(info.name));
        expect_same_either_way(scene.frame(kWidth, kHeight, info.frames / 3, info.frames), std::string(info.name) + " frame");
    }
    for (const raster::SeedSceneInfo& info : raster::seed_scenes()) {
        const raster::SeedScene scene(info.name);
        expect_same_either_way(scene.still(kWidth, kHeight), std::string(info.name));
        expect_same_either_way(scene.frame(kWidth, kHeight, info.frames / 3, info.frames), std::string(info.name) + " frame");
    }
}

TEST(DepthFirst, ChosenForOverlappingObjectsLitPerPixelOnly) {
    const auto chosen = [](const auto& scene) { return raster::detail::depth_first(scene, true, 320, 240); };
    EXPECT_TRUE(chosen(raster::SeedScene("flythrough").still(320, 240)));  // sea, sand and grass under every pixel
    EXPECT_FALSE(chosen(raster::SeedScene("ptah").still(320, 240)));       // one object
    EXPECT_FALSE(chosen(raster::DiaryScene("shaders").still(320, 240)));   // two tori side by side
    raster::PerspectiveScene flat = raster::SeedScene("flythrough").still(320, 240);
    for (raster::SceneObject& object : flat.objects) object.shading = raster::ShadingMethod::flat, object.texture = nullptr;
    EXPECT_FALSE(chosen(flat));  // cheap to shade: a second pass would cost more than it saves
}
