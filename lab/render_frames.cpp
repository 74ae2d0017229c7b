// render-frames: renders the 360 tumbling-cube frames in memory, without encoding, for profilers
// (valgrind --tool=callgrind build/release/lab/render-frames). Uses only the API of 0.0.7 onward,
// so the same file builds against older tags for comparison. `render-frames --time N` times, N
// times interleaved, clearing the 360 frames against rendering them (clear, then fill), in wall
// time, since callgrind counts each byte of a `rep movsb` as an instruction.
#include <raster/image/framebuffer.hpp>
#include <raster/scenes/scenes.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

template <typename Work>
double milliseconds_of(Work work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    raster::Framebuffer frame(raster::kSceneWidth, raster::kSceneHeight);
    const auto render_all = [&] {
        for (int i = 0; i < raster::kAnimationFrameCount; ++i) {
            raster::render_tumble_frame(frame, i, raster::kAnimationFrameCount, raster::CubeStyle::filled);
        }
    };
    if (argc != 3 || std::strcmp(argv[1], "--time") != 0) {
        render_all();
        std::printf("rendered %d frames\n", raster::kAnimationFrameCount);
        return 0;
    }
    const int repetitions = std::max(1, std::atoi(argv[2]));
    std::vector<double> clears, renders, fill_shares;
    for (int r = 0; r < repetitions; ++r) {
        clears.push_back(milliseconds_of([&] {
            for (int i = 0; i < raster::kAnimationFrameCount; ++i) frame.clear({0, 0, 0});
        }));
        renders.push_back(milliseconds_of(render_all));
        fill_shares.push_back((renders.back() - clears.back()) / renders.back());
    }
    std::printf("%d x 360 frames, 800x600, medians (min-max):\n", repetitions);
    std::printf("  clear  %.1f ms (%.1f-%.1f)\n", median(clears), *std::min_element(clears.begin(), clears.end()),
                *std::max_element(clears.begin(), clears.end()));
    std::printf("  render %.1f ms (%.1f-%.1f)\n", median(renders), *std::min_element(renders.begin(), renders.end()),
                *std::max_element(renders.begin(), renders.end()));
    std::printf("  fill share of the render %.0f %%\n", 100.0 * median(fill_shares));
}
