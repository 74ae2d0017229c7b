#pragma once

#include <string>
#include <string_view>
#include <vector>

// perspective-lab's second and third measures: clipping all six planes against a guard band,
// and which depth encodings keep two close floors in order.
namespace perspective_lab {

struct ClippingRow {
    std::string scene;
    int fov;
    long differing;
    double six_plane_ms, guard_band_ms;
};

ClippingRow measure_clipping(std::string_view name, int fov);

// Two floors 1e-5 apart seen from 1 above the nearer, looking 10 degrees down: at each pixel the
// nearer floor must win. Each encoding turns the exact view depths of both into what a buffer
// would store; a pixel is wrong when the farther floor's code is not larger.
struct DepthEncoding {
    std::string name;
    double (*code)(double w, double near, double far);
};

const std::vector<DepthEncoding>& encodings();

struct DepthRow {
    std::string encoding;
    double ratio;
    long wrong, compared;
};

std::vector<DepthRow> measure_depth();

}  // namespace perspective_lab
