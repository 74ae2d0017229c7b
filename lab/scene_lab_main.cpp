// scene-lab: tessellation, shading and depth formats against exact references; writes the CSV
// tables and scenes-summary.md that doc/lab/ shows, for lab/scene_charts.gp to draw.
#include "scene_lab.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string number(double value, const char* format = "%.3g") {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// On the front of the shading chart when no other row of the shape is at least as fast and as
// accurate inside the outline, and better in one (the outline has its own chart).
bool on_front(const lab::ShadingRow& row, const std::vector<lab::ShadingRow>& rows) {
    return std::none_of(rows.begin(), rows.end(), [&](const lab::ShadingRow& o) {
        return o.shape == row.shape && o.ms <= row.ms && o.max_error <= row.max_error &&
               (o.ms < row.ms || o.max_error < row.max_error);
    });
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "doc/lab";
    int repetitions = 11;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--out=", 0) == 0)
            out = arg.substr(6);
        else if (arg.rfind("--repetitions=", 0) == 0)
            repetitions = std::max(1, std::stoi(arg.substr(14)));
        else {
            std::cerr << "usage: scene-lab [--out=DIR] [--repetitions=N]\n";
            return 2;
        }
    }
    fs::create_directories(out);
    std::cerr << "scene-lab: shading and tessellation\n";
    const std::vector<lab::ShadingRow> shading = lab::measure_shading(repetitions);
    std::cerr << "scene-lab: depth formats\n";
    const std::vector<lab::DepthRow> depth = lab::measure_depth(repetitions);

    std::ofstream csv(out / "shading.csv");
    csv << "shape,level,facets,method,silhouette_px,outline_mismatches,mean_error,max_error,estimate,ms,ms_low,ms_high,"
           "pareto,diary,auto\n";
    for (const lab::ShadingRow& r : shading) {
        csv << r.shape << ',' << r.level << ',' << r.facets << ',' << r.method << ',' << r.silhouette_px << ','
            << r.outline_mismatches << ',' << r.mean_error << ',' << r.max_error << ',' << r.estimate << ',' << r.ms
            << ',' << r.ms_low << ',' << r.ms_high << ',' << on_front(r, shading) << ',' << r.diary << ','
            << r.automatic << '\n';
    }
    // The front, sorted by time per shape, for the chart's line.
    std::vector<lab::ShadingRow> front;
    for (const lab::ShadingRow& r : shading) {
        if (on_front(r, shading)) front.push_back(r);
    }
    std::sort(front.begin(), front.end(),
              [](const auto& a, const auto& b) { return a.shape != b.shape ? a.shape < b.shape : a.ms < b.ms; });
    std::ofstream front_csv(out / "shading-pareto.csv");
    front_csv << "shape,level,method,ms,max_error\n";
    for (const lab::ShadingRow& r : front)
        front_csv << r.shape << ',' << r.level << ',' << r.method << ',' << r.ms << ',' << r.max_error << '\n';
    std::ofstream depth_csv(out / "depth.csv");
    depth_csv << "scene,parameter,format,wrong_pixels,compared_pixels,ms\n";
    for (const lab::DepthRow& r : depth) {
        depth_csv << r.scene << ',' << r.parameter << ',' << r.format << ',' << r.wrong_pixels << ','
                  << r.compared_pixels << ',' << r.ms << '\n';
    }

    std::ofstream summary(out / "scenes-summary.md");
    summary << "# Scene lab summary\n\nWritten by `scene-lab` (`tools/bootstrap.sh lab`); medians of " << repetitions
            << " interleaved timings at 800 x 600. Errors are 8-bit levels against the ray-cast surface; "
               "the estimate is `shading_error_levels`, before rounding.\n";
    for (const std::string shape : {"sphere", "torus"}) {
        summary
            << "\n## " << shape
            << "\n\n| level | facets | method | outline (px) | outline mismatches | mean error | max error | estimate | ms (range) | |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
        for (const lab::ShadingRow& r : shading) {
            if (r.shape != shape) continue;
            std::string mark = r.automatic ? "auto" : "";
            if (r.diary) mark += mark.empty() ? "diary" : ", diary";
            if (on_front(r, shading)) mark += mark.empty() ? "front" : ", front";
            summary << "| " << r.level << " | " << r.facets << " | " << r.method << " | " << number(r.silhouette_px)
                    << " | " << r.outline_mismatches << " | " << number(r.mean_error, "%.3f") << " | "
                    << number(r.max_error, "%.0f") << " | " << number(r.estimate, "%.2f") << " | "
                    << number(r.ms, "%.2f") << " (" << number(r.ms_low, "%.2f") << "-" << number(r.ms_high, "%.2f")
                    << ") | " << mark << " |\n";
        }
    }
    summary
        << "\n## depth formats\n\n| scene | parameter | format | wrong pixels | of | ms |\n|---|---|---|---|---|---|\n";
    for (const lab::DepthRow& r : depth) {
        summary << "| " << r.scene << " | " << number(r.parameter) << " | " << r.format << " | " << r.wrong_pixels
                << " | " << r.compared_pixels << " | " << number(r.ms, "%.3f") << " |\n";
    }
    std::cerr << "scene-lab: wrote " << (out / "shading.csv").string() << ", depth.csv and scenes-summary.md\n";
    return 0;
}
