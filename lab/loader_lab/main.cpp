// loader-lab: which library should read glTF 2.0, STL, PLY and OBJ. On assimp's own test models it
// times the product's reader (raster::read_model), assimp alone, tinygltf (glTF only) and
// tinyobjloader (OBJ only), compares what each one read (triangles, vertices, bounding box,
// materials, textures), and feeds each of them assimp's malformed files in a child process, so
// that a crash or a hang is recorded rather than fatal.
// Writes loaders.csv and loaders-summary.md; lab/loader_chart.gp draws loaders.svg.
#include "loader_lab/cases.hpp"
#include "loader_lab/report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace loader_lab;

// One batch: the mean time of `count` loads, each one's triangles checked against the probe's.
double time_batch(Loader loader, const Case& c, int count) {
    const std::size_t expected = c.outcomes.at(loader).reading.triangles;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
        if (read_with(loader, c.path).triangles != expected)
            throw std::runtime_error(c.label + ": " + name_of(loader) + " read it differently twice");
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / count;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "doc/lab";
    fs::path models = "/usr/share/assimp/models";
    int rounds = 15;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--out=", 0) == 0) {
            out = arg.substr(6);
        } else if (arg.rfind("--models=", 0) == 0) {
            models = arg.substr(9);
        } else if (arg.rfind("--rounds=", 0) == 0) {
            rounds = std::max(1, std::atoi(arg.substr(9).c_str()));
        } else {
            std::cerr << "usage: loader-lab [--out=DIR] [--models=DIR (assimp-testmodels)] [--rounds=N]\n";
            return 2;
        }
    }
    fs::create_directories(out);
    std::vector<Case> all = cases(models);
    if (all.empty()) {
        std::cerr << "loader-lab: no test models under " << models.string() << " (apt-get install assimp-testmodels)\n";
        return 1;
    }
    // Every (file, loader) once in a child process first: what it read, refused, or died of.
    for (Case& c : all) {
        for (const Loader loader : kLoaders) {
            if (!reads(loader, c.path) ||
                (c.malformed && (loader == Loader::product_nomaps || loader == Loader::product_in_process)))
                continue;
            c.outcomes[loader] = probe(loader, c.path);
            Outcome& o = c.outcomes[loader];
            // The product names the file first ("file: ..." or "file:12: ..."); the tables already do.
            if (const std::string named = c.path.string() + ":"; o.message.rfind(named, 0) == 0) {
                o.message.erase(0, named.size());
                const std::size_t digits = o.message.find_first_not_of("0123456789");
                if (digits > 0 && digits != std::string::npos && o.message[digits] == ':')
                    o.message = "line " + o.message;
                if (o.message.rfind(' ', 0) == 0) o.message.erase(0, 1);
            }
            std::cerr << "loader-lab: " << c.label << ", " << name_of(loader) << ": " << o.status;
            if (o.status == "accepted") std::cerr << ", " << o.reading.triangles << " triangles";
            if (!o.message.empty()) std::cerr << " - " << o.message;
            std::cerr << '\n';
        }
        // Each accepted reading against every other accepted one of the same file.
        for (const auto& [loader, o] : c.outcomes) {
            if (o.status != "accepted") continue;
            std::string why;
            for (const auto& [other, p] : c.outcomes) {
                if (other == loader || p.status != "accepted") continue;
                const std::string d = difference(o.reading, p.reading);
                if (!d.empty()) why += (why.empty() ? "" : "; ") + std::string("vs ") + name_of(other) + ": " + d;
            }
            c.disagreements[loader] = why;
        }
    }
    // Timing, in this process, of well-formed files each loader accepted. A warm-up load sets the
    // batch; then round after round, every file by every loader, the loaders' order turning each
    // round so that none is always the first to touch a file.
    for (Case& c : all) {
        if (c.malformed) continue;
        for (const auto& [loader, o] : c.outcomes) {
            if (o.status != "accepted") continue;
            const double once = time_batch(loader, c, 1);
            c.batch[loader] =
                static_cast<int>(std::clamp(std::ceil(kSampleSeconds / std::max(once, 1e-9)), 1.0, 1000.0));
        }
    }
    for (int r = 0; r < rounds; ++r) {
        for (Case& c : all) {
            if (c.malformed || c.batch.empty()) continue;
            std::vector<Loader> order;
            for (const auto& [loader, count] : c.batch) order.push_back(loader);
            std::rotate(order.begin(), order.begin() + r % static_cast<int>(order.size()), order.end());
            for (const Loader loader : order) c.seconds[loader].push_back(time_batch(loader, c, c.batch[loader]));
        }
        std::cerr << "loader-lab: round " << r + 1 << " of " << rounds << " timed\n";
    }

    write_csv(all, models, out);
    write_summary(all, models, rounds, out);
    std::cerr << "loader-lab: wrote loaders.csv and loaders-summary.md in " << out.string() << "\n";
    return 0;
}
