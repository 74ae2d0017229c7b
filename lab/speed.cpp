#include "speed.hpp"

#include "corpus.hpp"

#include <raster/geometry/cube.hpp>
#include <raster/rasterize/draw_cube.hpp>
#include <raster/scenes/scenes.hpp>

#include <map>
#include <memory>
#include <benchmark/benchmark.h>

namespace lab {
namespace {

constexpr int kBatch = 64;  // primitives per benchmark iteration
constexpr PixelRect kTarget{0, 0, 1024, 1024};

// Primitives and pixels drawn per second, from the counts of one iteration.
void report_rates(benchmark::State& state, double primitives, double pixels) {
    state.counters["primitives"] = benchmark::Counter(primitives, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["pixels"] = benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
}

std::string key(std::string_view kind, std::string_view method, int size) {
    return std::string(kind) + "/" + std::string(method) + "/" + std::to_string(size);
}

// Collects each run's rates instead of only printing them.
class Collector : public benchmark::ConsoleReporter {
public:
    std::vector<SpeedResult> results;
    std::map<std::string, std::pair<std::string, int>> names;

    // With repetitions only the median is kept; a single run is kept as it is.
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            const bool usable =
                run.run_type == Run::RT_Aggregate ? run.aggregate_name == "median" : run.repetitions <= 1;
            const auto named = names.find(run.run_name.str());
            if (!usable || named == names.end() || run.error_occurred) continue;
            results.push_back({named->second.first, named->second.second, run.counters.at("primitives").value,
                               run.counters.at("pixels").value});
        }
    }
};

void register_fills(Collector& collector) {
    for (const FillMethod& method : fill_methods()) {
        for (const int size : kTriangleSizes) {
            auto triangles = std::make_shared<std::vector<std::vector<glm::dvec2>>>();
            double pixels = 0;
            Coverage reference(kTarget);
            for (const Polygon& polygon : triangles_of_size(size, kBatch, kTarget, static_cast<unsigned>(size))) {
                reference.clear();
                reference_polygon(polygon, reference);
                pixels += static_cast<double>(reference.total());
                std::vector<glm::dvec2> corners;
                for (const ExactPoint& p : polygon) corners.push_back(to_screen(p));
                triangles->push_back(corners);
            }
            const std::string name = key("fill", method.id, size);
            collector.names[name] = {std::string(method.id), size};
            benchmark::RegisterBenchmark(name.c_str(), [&method, triangles, pixels](benchmark::State& state) {
                Coverage target(kTarget);
                for (auto _ : state) {
                    for (const auto& corners : *triangles) method.fill(corners, target);
                    benchmark::ClobberMemory();
                }
                report_rates(state, kBatch, pixels);
            });
        }
    }
}

// The product's own scene: the front faces and culled edges of all 360 tumbling-cube frames.
struct TumbleScene {
    std::vector<std::vector<glm::dvec2>> faces;
    std::vector<std::pair<glm::ivec2, glm::ivec2>> edges;
};

TumbleScene tumble_scene() {
    TumbleScene scene;
    const raster::OrthoCamera camera(raster::kSceneWidth, raster::kSceneHeight);
    for (int frame = 0; frame < raster::kAnimationFrameCount; ++frame) {
        const raster::Cube cube = raster::Cube().posed(raster::tumble_pose(frame, raster::kAnimationFrameCount));
        const auto slots = raster::faces_toward_camera(camera, cube);
        for (const std::size_t slot : slots) {
            std::vector<glm::dvec2> corners;
            for (const std::size_t corner : cube.faces()[slot].corners) {
                const raster::SubpixelPoint p = *camera.subpixel_from_world(cube.corners()[corner]);
                corners.push_back({p.x / 256.0, p.y / 256.0});
            }
            scene.faces.push_back(corners);
        }
        for (const raster::Edge& edge : cube.edges_of(slots)) {
            scene.edges.push_back({*camera.pixel_from_world(cube.corners()[edge.from]),
                                   *camera.pixel_from_world(cube.corners()[edge.to])});
        }
    }
    return scene;
}

void register_scene(Collector& collector) {
    auto scene = std::make_shared<TumbleScene>(tumble_scene());
    const PixelRect frame{0, 0, raster::kSceneWidth, raster::kSceneHeight};
    Coverage reference(frame);
    for (const auto& corners : scene->faces) {
        std::vector<ExactPoint> exact;
        for (const glm::dvec2 c : corners) {
            exact.push_back({static_cast<std::int64_t>(c.x * kExactOne), static_cast<std::int64_t>(c.y * kExactOne)});
        }
        reference_polygon(exact, reference);
    }
    const double face_pixels = static_cast<double>(reference.total());
    reference.clear();
    for (const auto& [from, to] : scene->edges) reference_line(from, to, reference);
    const double edge_pixels = static_cast<double>(reference.total());
    const auto frames = static_cast<double>(raster::kAnimationFrameCount);

    for (const FillMethod& method : fill_methods()) {
        const std::string name = key("scene-fill", method.id, 0);
        collector.names[name] = {std::string(method.id), 0};
        benchmark::RegisterBenchmark(name.c_str(),
                                     [&method, scene, face_pixels, frames, frame](benchmark::State& state) {
                                         Coverage target(frame);
                                         for (auto _ : state) {
                                             for (const auto& corners : scene->faces) method.fill(corners, target);
                                             benchmark::ClobberMemory();
                                         }
                                         report_rates(state, frames, face_pixels);
                                     });
    }
    for (const LineMethod& method : line_methods()) {
        const std::string name = key("scene-line", method.id, 0);
        collector.names[name] = {std::string(method.id), 0};
        benchmark::RegisterBenchmark(name.c_str(), [&method, scene, edge_pixels, frames](benchmark::State& state) {
            raster::Framebuffer target(raster::kSceneWidth, raster::kSceneHeight);
            for (auto _ : state) {
                for (const auto& [from, to] : scene->edges) method.draw(target, {0, 0}, from, to);
                benchmark::ClobberMemory();
            }
            report_rates(state, frames, edge_pixels);
        });
    }
}

void register_lines(Collector& collector) {
    for (const LineMethod& method : line_methods()) {
        for (const int length : kLineLengths) {
            auto segments = std::make_shared<std::vector<std::pair<glm::ivec2, glm::ivec2>>>(
                segments_of_length(length, kBatch, {1024, 1024, 1, 1}, static_cast<unsigned>(length)));
            double pixels = 0;
            for (const auto& [from, to] : *segments) {
                Coverage reference({0, 0, 2048, 2048});
                reference_line(from, to, reference);
                pixels += static_cast<double>(reference.total());
            }
            const std::string name = key("line", method.id, length);
            collector.names[name] = {std::string(method.id), length};
            benchmark::RegisterBenchmark(name.c_str(), [&method, segments, pixels](benchmark::State& state) {
                raster::Framebuffer target(2048, 2048);
                for (auto _ : state) {
                    for (const auto& [from, to] : *segments) method.draw(target, {0, 0}, from, to);
                    benchmark::ClobberMemory();
                }
                report_rates(state, kBatch, pixels);
            });
        }
    }
}

}  // namespace

std::vector<SpeedResult> measure_speed(int argc, char** argv) {
    Collector collector;
    register_fills(collector);
    register_lines(collector);
    register_scene(collector);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks(&collector);
    benchmark::Shutdown();
    return collector.results;
}

}  // namespace lab
