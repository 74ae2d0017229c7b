#include <raster/scenes.hpp>
#include <raster/webp.hpp>

#include "support/golden.hpp"

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
    for (const CubeStyle style : {CubeStyle::filled, CubeStyle::wireframe, CubeStyle::culled_wireframe}) {
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
                                        for (int i = 0; i < shown; ++i) digests.push_back(test_support::digest_of(frame.image));
                                        return true;
                                    });
        EXPECT_TRUE(test_support::matches_digests(digests, "animated-cube/" + style_name(style)))
            << "doc/images/" << file << ".webp is stale: cmake --build --preset release --target update-snapshots";
    }
}
