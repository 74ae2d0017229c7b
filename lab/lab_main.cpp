// raster-lab: measures every raster method's accuracy against the exact reference and its speed,
// then writes CSV tables for the charts in doc/lab/.
#include "corpus.hpp"
#include "measures.hpp"
#include "speed.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Summary {
    std::string id;
    std::string label;
    bool is_product;
    double speed;  // geometric mean of pixels per second over the size classes
    double error;  // the chart's error axis
    bool pareto = false;
};

double geometric_mean_pixels(const std::vector<lab::SpeedResult>& speeds, std::string_view method) {
    double log_sum = 0.0;
    int count = 0;
    for (const lab::SpeedResult& s : speeds) {
        if (s.method != method) continue;
        log_sum += std::log(s.pixels_per_second);
        ++count;
    }
    return count == 0 ? 0.0 : std::exp(log_sum / count);
}

// A method is on the front when no other is at least as fast and as accurate, and better in one.
void mark_pareto(std::vector<Summary>& methods) {
    for (Summary& m : methods) {
        m.pareto = std::none_of(methods.begin(), methods.end(), [&m](const Summary& o) {
            return o.speed >= m.speed && o.error <= m.error && (o.speed > m.speed || o.error < m.error);
        });
    }
}

// Writes <name>.csv with every method and <name>-pareto.csv with the front, fastest first.
void write_summary(const fs::path& directory, const std::string& name, std::vector<Summary> methods,
                   const std::string& error_name) {
    std::sort(methods.begin(), methods.end(), [](const Summary& a, const Summary& b) { return a.speed > b.speed; });
    std::ofstream all(directory / (name + ".csv"));
    std::ofstream front(directory / (name + "-pareto.csv"));
    for (std::ofstream* out : {&all, &front}) *out << "method,label,product,mpixels_per_s," << error_name << ",pareto\n";
    for (const Summary& m : methods) {
        for (std::ofstream* out : {&all, &front}) {
            if (out == &front && !m.pareto) continue;
            *out << m.id << "," << m.label << "," << m.is_product << "," << m.speed / 1e6 << "," << m.error << ","
                 << m.pareto << "\n";
        }
    }
}

std::vector<Summary> measure_fills(const fs::path& out, const std::vector<lab::SpeedResult>& speeds) {
    std::ofstream table(out / "fill-accuracy.csv");
    table << "method,case,reference_pixels,mismatches,cracks,double_hits\n";
    const auto polygons = lab::polygon_corpora();
    const auto meshes = lab::mesh_cases();
    std::vector<Summary> summaries;
    for (const lab::FillMethod& method : lab::fill_methods()) {
        lab::FillAccuracy total;
        const auto add = [&](const std::string& name, const lab::FillAccuracy& a) {
            table << method.id << "," << name << "," << a.reference_pixels << "," << a.mismatches << "," << a.cracks
                  << "," << a.double_hits << "\n";
            total.reference_pixels += a.reference_pixels;
            total.mismatches += a.mismatches;
            total.cracks += a.cracks;
            total.double_hits += a.double_hits;
        };
        for (const auto& corpus : polygons) add(corpus.name, lab::measure_polygons(method, corpus));
        for (const auto& mesh : meshes) add(mesh.name, lab::measure_mesh(method, mesh));
        double motion = 0.0;
        for (const std::int64_t offset : lab::kOffsets) motion = std::max(motion, lab::measure_motion(method, offset));
        table << method.id << ",motion-max-px," << motion << ",,,\n";
        const double ppm = 1e6 * static_cast<double>(total.mismatches) / static_cast<double>(total.reference_pixels);
        std::cout << method.id << ": " << ppm << " mismatches per million, " << total.cracks << " cracks, "
                  << total.double_hits << " double hits, motion " << motion << " px\n";
        summaries.push_back({std::string(method.id), std::string(method.label), method.is_product,
                             geometric_mean_pixels(speeds, method.id), ppm});
    }
    mark_pareto(summaries);
    write_summary(out, "fill", summaries, "mismatches_per_million");
    return summaries;
}

std::vector<Summary> measure_lines(const fs::path& out, const std::vector<lab::SpeedResult>& speeds) {
    std::ofstream table(out / "line-accuracy.csv");
    table << "method,case,reference_pixels,mismatches,max_distance,outside_3x3,count_difference,max_count_difference,steps\n";
    std::vector<Summary> summaries;
    for (const lab::LineMethod& method : lab::line_methods()) {
        std::int64_t reference = 0, mismatches = 0;
        for (const auto& corpus : lab::segment_corpora()) {
            const lab::LineAccuracy a = lab::measure_segments(method, corpus);
            table << method.id << "," << corpus.name << "," << a.reference_pixels << "," << a.mismatches << ","
                  << a.max_distance << "," << a.outside_neighbourhood << "," << a.count_difference << ","
                  << a.max_count_difference << "," << a.steps << "\n";
            reference += a.reference_pixels;
            mismatches += a.mismatches;
        }
        const double ppm = 1e6 * static_cast<double>(mismatches) / static_cast<double>(reference);
        std::cout << method.id << ": " << ppm << " mismatches per million\n";
        summaries.push_back({std::string(method.id), std::string(method.label), method.is_product,
                             geometric_mean_pixels(speeds, method.id), ppm});
    }
    mark_pareto(summaries);
    write_summary(out, "line", summaries, "mismatches_per_million");
    return summaries;
}

void write_speeds(const fs::path& out, const std::vector<lab::SpeedResult>& speeds) {
    std::ofstream table(out / "speed.csv");
    table << "method,size,primitives_per_s,mpixels_per_s\n";
    for (const lab::SpeedResult& s : speeds) {
        table << s.method << "," << s.size << "," << s.primitives_per_second << "," << s.pixels_per_second / 1e6 << "\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "doc/lab";
    std::vector<char*> passed{argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--out=", 6) == 0) out = argv[i] + 6;
        else passed.push_back(argv[i]);
    }
    fs::create_directories(out);
    int passed_count = static_cast<int>(passed.size());
    const std::vector<lab::SpeedResult> speeds = lab::measure_speed(passed_count, passed.data());
    write_speeds(out, speeds);
    measure_fills(out, speeds);
    measure_lines(out, speeds);
    std::cout << "raster-lab: wrote CSV tables to " << out.string() << "\n";
}
