// raster-lab: measures every raster method's accuracy against the exact reference and its speed,
// then writes the CSV tables and summary.md that doc/lab/ shows.
#include "corpus.hpp"
#include "measures.hpp"
#include "speed.hpp"

#include <raster/platform/cores.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Row {
    std::string id;
    std::string label;
    bool is_product = false;
    double speed = 0.0;                // million pixels per second on the tumbling-cube scene: the chart's speed axis
    double error = 0.0;                // mismatches per million reference pixels: the chart's error axis
    std::vector<std::string> details;  // further columns of the summary table
    bool pareto = false;
};

double scene_mpixels(const std::vector<lab::SpeedResult>& speeds, std::string_view method) {
    for (const lab::SpeedResult& s : speeds) {
        if (s.method == method && s.size == 0) return s.pixels_per_second / 1e6;
    }
    return 0.0;
}

double geometric_mean_mpixels(const std::vector<lab::SpeedResult>& speeds, std::string_view method) {
    double log_sum = 0.0;
    int count = 0;
    for (const lab::SpeedResult& s : speeds) {
        if (s.method != method || s.size == 0) continue;
        log_sum += std::log(s.pixels_per_second / 1e6);
        ++count;
    }
    return count == 0 ? 0.0 : std::exp(log_sum / count);
}

std::string fixed(double value, int decimals) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(decimals) << value;
    return text.str();
}

// A method is on the front when no other is at least as fast and as accurate, and better in one.
void rank(std::vector<Row>& rows) {
    for (Row& m : rows) {
        m.pareto = std::none_of(rows.begin(), rows.end(), [&m](const Row& o) {
            return o.speed >= m.speed && o.error <= m.error && (o.speed > m.speed || o.error < m.error);
        });
    }
    std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.speed > b.speed; });
}

// <name>.csv holds every method and <name>-pareto.csv the front, fastest first, for the charts.
void write_chart_tables(const fs::path& directory, const std::string& name, const std::vector<Row>& rows) {
    std::ofstream all(directory / (name + ".csv"));
    std::ofstream front(directory / (name + "-pareto.csv"));
    for (std::ofstream* out : {&all, &front})
        *out << "method,label,product,mpixels_per_s,mismatches_per_million,pareto\n";
    for (const Row& m : rows) {
        for (std::ofstream* out : {&all, &front}) {
            if (out == &front && !m.pareto) continue;
            *out << m.id << "," << m.label << "," << m.is_product << "," << m.speed << "," << m.error << "," << m.pareto
                 << "\n";
        }
    }
}

void write_markdown_table(std::ostream& out, const std::vector<std::string>& header, const std::vector<Row>& rows) {
    out << "| method | Mpixels/s on the tumbling cube | mismatches per million |";
    for (const std::string& h : header) out << " " << h << " |";
    out << " Pareto front |\n|---|---|---|";
    for (std::size_t i = 0; i < header.size(); ++i) out << "---|";
    out << "---|\n";
    for (const Row& m : rows) {
        out << "| " << m.label << " (`" << m.id << "`) | " << fixed(m.speed, 1) << " | " << fixed(m.error, 1) << " |";
        for (const std::string& d : m.details) out << " " << d << " |";
        out << " " << (m.pareto ? "yes" : "no") << " |\n";
    }
}

void write_speed_table(std::ostream& out, const std::vector<lab::SpeedResult>& speeds, const std::vector<Row>& rows,
                       std::span<const int> sizes, const std::string& size_name) {
    out << "| " << size_name << " |";
    for (const Row& m : rows) out << " `" << m.id << "` |";
    out << " fastest |\n|---|";
    for (std::size_t i = 0; i < rows.size(); ++i) out << "---|";
    out << "---|\n";
    for (const int size : sizes) {
        out << "| " << size << " |";
        std::string fastest;
        double best = 0.0;
        for (const Row& m : rows) {
            for (const lab::SpeedResult& s : speeds) {
                if (s.method != m.id || s.size != size) continue;
                out << " " << fixed(s.pixels_per_second / 1e6, 1) << " |";
                if (s.pixels_per_second > best) best = s.pixels_per_second, fastest = m.id;
            }
        }
        out << " `" << fastest << "` |\n";
    }
}

std::vector<Row> measure_fills(const fs::path& out, const std::vector<lab::SpeedResult>& speeds) {
    std::ofstream table(out / "fill-accuracy.csv");
    table << "method,case,reference_pixels,mismatches,cracks,double_hits\n";
    const auto polygons = lab::polygon_corpora();
    const auto meshes = lab::mesh_cases();
    std::vector<Row> rows;
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
        const double ppm = 1e6 * static_cast<double>(total.mismatches) / static_cast<double>(total.reference_pixels);
        rows.push_back(
            {std::string(method.id),
             std::string(method.label),
             method.is_product,
             scene_mpixels(speeds, method.id),
             ppm,
             {fixed(geometric_mean_mpixels(speeds, method.id), 1), std::to_string(total.cracks),
              std::to_string(total.double_hits), std::isfinite(motion) ? fixed(motion, 3) : "lost the triangle"}});
    }
    rank(rows);
    write_chart_tables(out, "fill", rows);
    return rows;
}

std::vector<Row> measure_lines(const fs::path& out, const std::vector<lab::SpeedResult>& speeds) {
    std::ofstream table(out / "line-accuracy.csv");
    table
        << "method,case,reference_pixels,mismatches,max_distance,outside_3x3,count_difference,max_count_difference,steps\n";
    std::vector<Row> rows;
    for (const lab::LineMethod& method : lab::line_methods()) {
        std::int64_t reference = 0, mismatches = 0, outside = 0, count_difference = 0;
        double distance = 0.0;
        for (const auto& corpus : lab::segment_corpora()) {
            const lab::LineAccuracy a = lab::measure_segments(method, corpus);
            table << method.id << "," << corpus.name << "," << a.reference_pixels << "," << a.mismatches << ","
                  << a.max_distance << "," << a.outside_neighbourhood << "," << a.count_difference << ","
                  << a.max_count_difference << "," << a.steps << "\n";
            reference += a.reference_pixels;
            mismatches += a.mismatches;
            outside += a.outside_neighbourhood;
            count_difference = std::max(count_difference, a.max_count_difference);
            distance = std::max(distance, a.max_distance);
        }
        const double ppm = 1e6 * static_cast<double>(mismatches) / static_cast<double>(reference);
        rows.push_back({std::string(method.id),
                        std::string(method.label),
                        method.is_product,
                        scene_mpixels(speeds, method.id),
                        ppm,
                        {fixed(geometric_mean_mpixels(speeds, method.id), 1), fixed(distance, 3),
                         std::to_string(outside), std::to_string(count_difference)}});
    }
    rank(rows);
    write_chart_tables(out, "line", rows);
    return rows;
}

std::string machine() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown CPU";
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "doc/lab";
    std::vector<char*> passed{argv[0]};
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--out=", 6) == 0)
            out = argv[i] + 6;
        else
            passed.push_back(argv[i]);
    }
    fs::create_directories(out);
    int passed_count = static_cast<int>(passed.size());
    const std::vector<lab::SpeedResult> speeds = lab::measure_speed(passed_count, passed.data());
    {
        std::ofstream table(out / "speed.csv");
        table << "method,size,primitives_per_s,mpixels_per_s\n";
        for (const lab::SpeedResult& s : speeds) {
            table << s.method << "," << s.size << "," << s.primitives_per_second << "," << s.pixels_per_second / 1e6
                  << "\n";
        }
    }
    const std::vector<Row> fills = measure_fills(out, speeds);
    const std::vector<Row> lines = measure_lines(out, speeds);

    std::ofstream summary(out / "summary.md");
    summary << "# Lab results\n\nWritten by `raster-lab` on " << machine() << " (" << raster::available_cores()
            << " cores). Speeds are medians of repeated Google Benchmark runs; the speed that decides the "
               "Pareto front is measured on the product's own scene, the front faces (fills) or culled edges "
               "(lines) of all 360 tumbling-cube frames at 800x600. Every figure comes from the CSV tables "
               "beside this file.\n\n## Convex fills\n\n";
    write_markdown_table(
        summary, {"Mpixels/s, geometric mean over sizes", "cracks", "double hits", "motion: worst centroid error (px)"},
        fills);
    summary << "\nMillion pixels per second by triangle size (px):\n\n";
    write_speed_table(summary, speeds, fills, lab::kTriangleSizes, "size");
    summary << "\n## Lines\n\n";
    write_markdown_table(summary,
                         {"Mpixels/s, geometric mean over lengths", "farthest pixel from the segment (px)",
                          "pixels outside the reference's 3x3", "worst pixel-count difference"},
                         lines);
    summary << "\nMillion pixels per second by segment length (px):\n\n";
    write_speed_table(summary, speeds, lines, lab::kLineLengths, "length");
    std::cout << "raster-lab: wrote " << (out / "summary.md").string() << " and its CSV tables\n";
}
