#include "speed.hpp"

#include "corpus.hpp"

#include <benchmark/benchmark.h>
#include <map>
#include <memory>

namespace lab {
namespace {

constexpr int kBatch = 64;  // primitives per benchmark iteration
constexpr PixelRect kTarget{0, 0, 1024, 1024};

std::string key(std::string_view kind, std::string_view method, int size) {
    return std::string(kind) + "/" + std::string(method) + "/" + std::to_string(size);
}

// Collects each run's rates instead of only printing them.
class Collector : public benchmark::ConsoleReporter {
public:
    std::vector<SpeedResult> results;
    std::map<std::string, std::pair<std::string, int>> names;

    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            const auto named = names.find(run.benchmark_name());
            if (named == names.end() || run.error_occurred) continue;
            results.push_back({named->second.first, named->second.second,
                               run.counters.at("primitives").value, run.counters.at("pixels").value});
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
                state.counters["primitives"] = benchmark::Counter(kBatch, benchmark::Counter::kIsIterationInvariantRate);
                state.counters["pixels"] = benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
            });
        }
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
                state.counters["primitives"] = benchmark::Counter(kBatch, benchmark::Counter::kIsIterationInvariantRate);
                state.counters["pixels"] = benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
            });
        }
    }
}

}  // namespace

std::vector<SpeedResult> measure_speed(int argc, char** argv) {
    Collector collector;
    register_fills(collector);
    register_lines(collector);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks(&collector);
    benchmark::Shutdown();
    return collector.results;
}

}  // namespace lab
