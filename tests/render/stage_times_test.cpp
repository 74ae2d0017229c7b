// render --timings' stages: the one-core estimate, and frames timed by a Renderer drawn as they are untimed.
#include <raster/render/scene.hpp>
#include <raster/render/stage_times.hpp>

#include <memory>
#include <vector>
#include <gtest/gtest.h>

namespace {

// An unlit square facing the camera at depth z, `alpha` below 1 blended.
raster::SceneObject square(float z, float alpha) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions = {{-0.6F, -0.6F, z}, {0.6F, -0.6F, z}, {0.6F, 0.6F, z}, {-0.6F, 0.6F, z}};
    mesh->normals.assign(4, {0.0F, 0.0F, -1.0F});
    const glm::vec3 behind(0.0F, 0.0F, z + 1.0F);
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    raster::SceneObject object{mesh, glm::mat4(1.0F),
                               raster::LinearMaterial{{0, 0, 0}, {0.2F, 0.6F, 0.9F}, {0, 0, 0}, {}},
                               raster::ShadingMethod::unlit};
    object.opacity = {alpha < 1.0F ? raster::AlphaMode::blend : raster::AlphaMode::opaque, alpha, 0.5F};
    return object;
}

raster::Scene scene_of(std::vector<raster::SceneObject> objects) {
    raster::Scene scene{raster::OrthoCamera(40, 150), {10, 20, 30}, {}, {}, {}};
    scene.objects = std::move(objects);
    return scene;
}

}  // namespace

TEST(StageTimes, OneCoreEstimateIsWholeForOneThreadsWorkAndNoneForAllThreads) {
    for (const int threads : {2, 3, 16}) {
        EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(2.0, 2.0, threads), 1.0) << threads;  // C = W
        EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(2.0, 2.0 * threads, threads), 0.0);   // C = T W
        EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(2.0, 0.5, threads), 1.0);             // waiting: clamped
        EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(2.0, 40.0, threads), 0.0);  // more than T W: clamped
    }
    EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(1.0, 1.5, 2), 0.5);  // half serial, half on both
    EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(1.0, 1.0, 1), 1.0);  // one thread: all of it
    EXPECT_DOUBLE_EQ(raster::estimated_one_core_share(0.0, 0.0, 4), 0.0);  // no time, no share
}

TEST(StageTimes, CountedShareIsTheOneCoreTimeOverTheWall) {
    raster::StageTime counted{{2.0, 3.0}, 0.5, true};
    EXPECT_DOUBLE_EQ(raster::one_core_share(counted, 4), 0.25);
    counted.counted = false;  // then estimated: (4*2 - 3) / (3*2)
    EXPECT_DOUBLE_EQ(raster::one_core_share(counted, 4), 5.0 / 6.0);
}

TEST(StageTimes, ATimedFrameIsTheUntimedOneWithItsDrawAndResolveCounted) {
    for (const int samples : {1, 4}) {
        for (const bool blended : {false, true}) {
            const raster::Scene scene = scene_of({square(2.0F, 1.0F), square(1.0F, blended ? 0.5F : 1.0F)});
            raster::Renderer renderer({.threads = 2, .samples = samples});
            raster::Framebuffer plain(40, 150), timed(40, 150);
            renderer.render(plain, scene);
            raster::StageTimes times;
            renderer.render(timed, scene, &times);
            renderer.render(timed, scene, &times);  // a second frame adds to the first
            EXPECT_EQ(timed, plain) << samples << " samples, blended " << blended;
            EXPECT_EQ(times.threads, 2);
            EXPECT_TRUE(times.draw.counted);
            EXPECT_TRUE(times.resolve.counted);
            EXPECT_GE(times.draw.one_core, 0.0);
            EXPECT_EQ(times.resolve_in_draw, blended) << samples << " samples";
            // Only multisampled opaque frames resolve apart; the others have no resolve of their own.
            if (samples == 1 || blended) {
                EXPECT_EQ(times.resolve.spent.wall, 0.0) << samples << " samples";
            }
            EXPECT_EQ(times.read.spent.wall, 0.0);  // a renderer times its frames only
        }
    }
}
