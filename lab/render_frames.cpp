// render-frames: renders the 360 tumbling-cube frames in memory, without encoding, for profilers
// (valgrind --tool=callgrind build/release/lab/render-frames). Uses only the API of 0.0.7 onward,
// so the same file builds against older tags for comparison.
#include <raster/framebuffer.hpp>
#include <raster/scenes.hpp>

#include <cstdio>

int main() {
    raster::Framebuffer frame(raster::kSceneWidth, raster::kSceneHeight);
    for (int i = 0; i < raster::kAnimationFrameCount; ++i) {
        raster::render_tumble_frame(frame, i, raster::kAnimationFrameCount, raster::CubeStyle::filled);
    }
    std::printf("rendered %d frames\n", raster::kAnimationFrameCount);
}
