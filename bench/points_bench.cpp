// points-bench: splats per second once loaded. A Fibonacci sphere of N lit, coloured points is
// rendered at 800 x 600 on the threads asked for, the runs interleaved with a run of the same
// cloud unlit; prints the median and the range of each, and the median processor time a frame
// (all threads), which a busy machine inflates less than the wall clock (doc/conventions.md#points-and-lines).
#include <raster/render/scene.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

namespace {

std::shared_ptr<raster::Mesh> cloud(std::size_t n) {
    auto mesh = std::make_shared<raster::Mesh>();
    mesh->positions.reserve(n), mesh->normals.reserve(n), mesh->colours.reserve(n), mesh->points.reserve(n);
    const double turn = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        const double r = std::sqrt(1.0 - y * y), a = turn * static_cast<double>(i);
        const glm::vec3 p(static_cast<float>(r * std::cos(a)), static_cast<float>(y),
                          static_cast<float>(r * std::sin(a)));
        mesh->positions.push_back(p);
        mesh->normals.push_back(p);
        mesh->colours.push_back({0.5F + 0.5F * p.x, 0.5F + 0.5F * p.y, 0.5F + 0.5F * p.z});
        mesh->points.push_back(static_cast<std::uint32_t>(i));
    }
    return mesh;
}

struct Times {
    double wall;
    double processor;  // every thread's
};

Times seconds(raster::Framebuffer& image, const raster::Scene& scene, raster::RenderOptions options) {
    raster::DepthBuffer depth;
    const std::clock_t processor = std::clock();
    const auto start = std::chrono::steady_clock::now();
    raster::render(image, scene, depth, options);
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
            static_cast<double>(std::clock() - processor) / CLOCKS_PER_SEC};
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "--help") {
        std::puts("usage: points-bench [POINTS [THREADS [SAMPLES [REPEATS]]]]   (defaults 10000000 2 1 5)");
        return 0;
    }
    const auto arg = [&](int i, long fallback) { return argc > i ? std::atol(argv[i]) : fallback; };
    const auto n = static_cast<std::size_t>(std::max(arg(1, 10000000), 1L));
    const int threads = static_cast<int>(arg(2, 2)), samples = static_cast<int>(arg(3, 1));
    const int repeats = static_cast<int>(std::max(arg(4, 5), 1L));
    raster::Scene lit{raster::OrthoCamera::look_at(800, 600, {0.0F, 0.6F, -2.5F}), {20, 22, 28}, {}, {}, {}};
    lit.lights = {{{-0.5F, 0.8F, -0.6F}, 1.0F}};
    lit.objects.push_back({cloud(n), glm::mat4(1.0F),
                           raster::LinearMaterial{{0, 0, 0}, {1, 1, 1}, {0.3F, 0.3F, 0.3F}, 20.0F},
                           raster::ShadingMethod::phong});
    raster::Scene unlit = lit;
    unlit.objects.front().shading = raster::ShadingMethod::unlit;
    raster::Framebuffer image(800, 600);
    std::vector<Times> lit_times, unlit_times;
    for (int r = 0; r < repeats; ++r) {  // interleaved, so drift in the machine touches both alike
        lit_times.push_back(seconds(image, lit, {.threads = threads, .samples = samples}));
        unlit_times.push_back(seconds(image, unlit, {.threads = threads, .samples = samples}));
    }
    const auto report = [&](const char* name, std::vector<Times> times) {
        const auto median = [&](auto field) {
            std::sort(times.begin(), times.end(), [&](const Times& a, const Times& b) { return a.*field < b.*field; });
            return std::tuple{times[times.size() / 2].*field, times.front().*field, times.back().*field};
        };
        const auto [wall, fastest, slowest] = median(&Times::wall);
        const double processor = std::get<0>(median(&Times::processor));
        const auto rate = [&](double s) { return static_cast<double>(n) / s / 1e6; };
        std::printf("%-6s %zu points, %d threads, %d samples: median %.3f s (%.3f..%.3f), %.1f M points/s, %.1f M/s "
                    "per thread; processor %.3f s a frame, %.1f M points/s per processor-second\n",
                    name, n, threads, samples, wall, fastest, slowest, rate(wall), rate(wall) / threads, processor,
                    rate(processor));
    };
    report("phong", lit_times);
    report("unlit", unlit_times);
    return 0;
}
