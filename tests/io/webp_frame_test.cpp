#include <raster/scenes/scenes.hpp>
#include <raster/io/webp.hpp>

#include "support/scratch.hpp"

#include <gtest/gtest.h>

using raster::Framebuffer;
using test_support::kAnimatedCube;
using test_support::kWebpFrame;
using test_support::run;
using test_support::ScratchDir;


TEST(WebpFrameApp, WritesFrameNAsTheWholePictureAPlayerShows) {
    const ScratchDir dir;
    ASSERT_EQ(run(kAnimatedCube, {"--frames", "12", "--width", "96", "--height", "72", "spin.webp"}, dir.path()).exit_code, 0);
    Framebuffer expected(96, 72);
    for (const int index : {0, 5, 11}) {
        const std::string out = "frame-" + std::to_string(index) + ".webp";
        const auto result = run(kWebpFrame, {"spin.webp", std::to_string(index), out}, dir.path());
        EXPECT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(result.out.rfind("Wrote " + out + ": frame " + std::to_string(index) + " of spin.webp, 96x72, ", 0), 0U)
            << result.out;
        const raster::DecodedWebp still = raster::read_webp(dir / out);
        ASSERT_EQ(still.frames.size(), 1U);
        raster::render_tumble_frame(expected, index, 12, raster::CubeStyle::filled);
        EXPECT_EQ(still.frames[0].image, expected) << "frame " << index;
    }
}

TEST(WebpFrameApp, FrameZeroOfAStillIsTheStill) {
    const ScratchDir dir;
    Framebuffer image(5, 4);
    image.set_pixel(2, 1, {1, 2, 3});
    raster::write_webp_still(image, dir / "still.webp");
    EXPECT_EQ(run(kWebpFrame, {"still.webp", "0", "-o", "copy.webp"}, dir.path()).exit_code, 0);
    EXPECT_EQ(raster::read_webp(dir / "copy.webp").frames.at(0).image, image);
}
