#pragma once

#include "fill_methods.hpp"
#include "line_methods.hpp"

#include <string>
#include <vector>

// Speed, measured with Google Benchmark on identical inputs for every method.
namespace lab {

struct SpeedResult {
    std::string method;
    int size;                      // triangle size or line length in pixels; 0 for the tumbling-cube scene
    double primitives_per_second;  // frames per second for the scene
    double pixels_per_second;      // pixels the reference covers, per second
};

inline constexpr int kTriangleSizes[] = {1, 4, 16, 64, 256, 500};
inline constexpr int kLineLengths[] = {1, 10, 100, 1000};

// Runs every benchmark; extra arguments go to Google Benchmark (for example --benchmark_min_time).
[[nodiscard]] std::vector<SpeedResult> measure_speed(int argc, char** argv);

}  // namespace lab
