#include "loader_lab/report.hpp"

#include "lab_args.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace loader_lab {
namespace {

// Milliseconds to three significant figures, without an exponent.
std::string ms(double seconds) {
    const double v = seconds * 1000.0;
    char text[32];
    std::snprintf(text, sizeof text, v >= 100 ? "%.0f" : v >= 10 ? "%.1f" : v >= 1 ? "%.2f" : "%.3f", v);
    return text;
}

std::string point(const glm::dvec3& p) {
    char text[100];
    std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
    return text;
}

double quantile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

}  // namespace

void write_csv(const std::vector<Case>& all, const fs::path& models, const fs::path& out) {
    std::ofstream csv(out / "loaders.csv");
    csv << "kind,file_index,file,path,loader,status,samples,batch,median_ms,q1_ms,q3_ms,min_ms,max_ms,triangles,flat,vertices,materials,textures,"
           "low_x,low_y,low_z,high_x,high_y,high_z,agrees,message\n";
    int index = 0;
    for (const Case& c : all) {
        for (const auto& [loader, o] : c.outcomes) {
            csv << (c.malformed ? "malformed" : "wellformed") << ',' << index << ',' << field(c.label) << ','
                << field(fs::relative(c.path, models).string()) << ',' << name_of(loader) << ',' << field(o.status)
                << ',';
            const auto times = c.seconds.find(loader);
            if (times != c.seconds.end()) {
                const std::vector<double>& t = times->second;
                csv << t.size() << ',' << c.batch.at(loader) << ',' << lab::median(t) * 1e3 << ','
                    << quantile(t, 0.25) * 1e3 << ',' << quantile(t, 0.75) * 1e3 << ','
                    << *std::min_element(t.begin(), t.end()) * 1e3 << ',' << *std::max_element(t.begin(), t.end()) * 1e3
                    << ',';
            } else {
                csv << ",,,,,,,";
            }
            if (o.status == "accepted") {
                const Reading& g = o.reading;
                csv << g.triangles << ',' << g.flat << ',' << g.vertices << ',' << g.materials << ',' << g.textures
                    << ',' << g.box.low.x << ',' << g.box.low.y << ',' << g.box.low.z << ',' << g.box.high.x << ','
                    << g.box.high.y << ',' << g.box.high.z << ',' << (c.disagreements.at(loader).empty() ? "yes" : "no")
                    << ',';
            } else {
                csv << ",,,,,,,,,,,,";
            }
            const std::string& why =
                o.status == "accepted" && !c.disagreements.at(loader).empty() ? c.disagreements.at(loader) : o.message;
            csv << field(why) << '\n';
        }
        ++index;
    }
}

void write_summary(const std::vector<Case>& all, const fs::path& models, int rounds, const fs::path& out) {
    std::ofstream summary(out / "loaders-summary.md");
    summary << "Load time, ms: median of " << rounds << " rounds (each the mean of a batch of loads lasting about "
            << kSampleSeconds * 1e3 << " ms), with the fastest and slowest round. Files from assimp-testmodels ("
            << models.string() << ").\n\n";
    summary
        << "| file | triangles in the file | product | product-nomaps | product-in-process | assimp | tinygltf | tinyobjloader |\n|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : all) {
        if (c.malformed) continue;
        std::size_t triangles = 0;
        for (const auto& [loader, o] : c.outcomes) {
            if (o.status == "accepted") triangles = std::max(triangles, o.reading.triangles);
        }
        summary << "| " << c.label << " | " << triangles;
        for (const Loader loader : kLoaders) {
            const auto o = c.outcomes.find(loader);
            summary << " | ";
            if (o == c.outcomes.end()) {
                summary << "-";
            } else if (const auto t = c.seconds.find(loader); t != c.seconds.end()) {
                summary << ms(lab::median(t->second)) << " ("
                        << ms(*std::min_element(t->second.begin(), t->second.end())) << "-"
                        << ms(*std::max_element(t->second.begin(), t->second.end())) << ")";
            } else {
                summary << o->second.status;
            }
        }
        summary << " |\n";
    }
    summary
        << "\nWhat each read (the file's own axes; assimp and tinygltf placed by the node matrices, as the product is). No area: "
           "triangles whose corners the product's facet_normal finds collinear or coincident (it drops them). Agrees: as many triangles "
           "with area, in a bounding box within "
        << kBoxTolerance << " of its diagonal, as every other loader that accepted the file.\n\n";
    summary
        << "| file | loader | triangles | no area | vertices | materials | textures | box min | box max | agrees |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : all) {
        if (c.malformed) continue;
        for (const auto& [loader, o] : c.outcomes) {
            summary << "| " << c.label << " | " << name_of(loader) << " | ";
            if (o.status != "accepted") {
                summary << o.status << (o.message.empty() ? "" : ": " + one_line(o.message, 100))
                        << " | | | | | | | |\n";
                continue;
            }
            const Reading& g = o.reading;
            const std::string& why = c.disagreements.at(loader);
            summary << g.triangles << " | " << g.flat << " | " << g.vertices << " | " << g.materials << " | "
                    << g.textures << " | " << point(g.box.low) << " | " << point(g.box.high) << " | "
                    << (why.empty() ? "yes" : "no: " + why) << " |\n";
        }
    }
    summary << "\nMalformed files, each loader run once in a child process (killed after " << kProbeSeconds
            << " s).\n\n";
    summary << "| file | product | assimp | tinygltf | tinyobjloader |\n|---|---|---|---|---|\n";
    for (const Case& c : all) {
        if (!c.malformed) continue;
        summary << "| " << c.label;
        for (const Loader loader : {Loader::product, Loader::assimp, Loader::tinygltf, Loader::tinyobjloader}) {
            const auto o = c.outcomes.find(loader);
            summary << " | ";
            if (o == c.outcomes.end()) {
                summary << "-";
                continue;
            }
            summary << o->second.status;
            if (o->second.status == "accepted") summary << ", " << o->second.reading.triangles << " triangles";
            if (!o->second.message.empty()) summary << ": " << one_line(o->second.message, 90);
        }
        summary << " |\n";
    }
}

}  // namespace loader_lab
