#pragma once

#include <cstdint>
#include <string>
#include <vector>

// The scene lab: tessellation, shading method and depth format, each measured against an exact
// reference and timed on the product's own rasterizer (doc/lab/README.md).
namespace lab {

struct ShadingRow {
    std::string shape;  // "sphere" or "torus"
    int level;          // raster::tessellate level
    std::size_t facets;
    std::string method;               // "flat", "gouraud", "phong"
    double silhouette_px;             // farthest mesh point from the true surface, times the scale on screen
    std::int64_t outline_mismatches;  // pixels covered by one of mesh and true surface only
    double mean_error;                // 8-bit levels, over pixels inside both outlines (3 x 3 covered)
    double max_error;
    double estimate;         // raster::shading_error_levels, levels before rounding
    double ms;               // median milliseconds to render the frame (clear included)
    double ms_low, ms_high;  // their range
    bool diary = false;      // the release's own choice
    bool automatic = false;  // what --detail auto picks
};

// The phong-sphere still (radius 210 px) and the torus still (0.8 scale) at 800 x 600, every
// level and method; `repetitions` interleaved timings each.
[[nodiscard]] std::vector<ShadingRow> measure_shading(int repetitions);

struct DepthRow {
    std::string scene;  // "crossing" (angle in degrees) or "gap" (world units between planes)
    double parameter;
    std::string format;  // "float32", "fixed24", "fixed16"
    std::int64_t wrong_pixels;
    std::int64_t compared_pixels;
    double ms;
};

[[nodiscard]] std::vector<DepthRow> measure_depth(int repetitions);

}  // namespace lab
