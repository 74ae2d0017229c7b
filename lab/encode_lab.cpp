// encode-lab: how the tumbling cube's 360 frames (800 x 600, animated-cube's defaults) are best
// encoded. Every path, effort and thread count, and the parallel path's method and quality,
// timed against the file size; each file decoded and checked against the frames.
// Writes encode.csv and encode-summary.md; lab/encode_chart.gp draws encode.svg.
#include "lab_args.hpp"

#include <raster/io/webp.hpp>
#include <raster/scenes/scenes.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct Config {
    std::string name;
    raster::AnimationSettings settings;
    std::vector<double> seconds{};
    std::size_t bytes = 0;
};

std::vector<Config> configs() {
    using raster::AnimationPath;
    using raster::Effort;
    std::vector<Config> all;
    for (const auto& [name, effort] :
         {std::pair{"fast", Effort::fast}, std::pair{"default", Effort::balanced}, std::pair{"max", Effort::max}}) {
        all.push_back({std::string("anim ") + name, {effort, AnimationPath::anim, 1}});
        for (const int threads : {1, 2}) {
            all.push_back({std::string("parallel ") + name + " x" + std::to_string(threads),
                           {effort, AnimationPath::parallel, threads}});
        }
    }
    for (const int method : {0, 1, 2, 3, 4}) {
        for (const float quality : {0.0F, 50.0F, 100.0F}) {
            raster::AnimationSettings s{Effort::balanced, AnimationPath::parallel, 2,
                                        raster::LosslessTuning{method, quality}};
            all.push_back(
                {"parallel m" + std::to_string(method) + " q" + std::to_string(static_cast<int>(quality)) + " x2", s});
        }
    }
    return all;
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path out = "doc/lab";
    int repetitions = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--out=", 0) == 0) {
            out = arg.substr(6);
        } else if (arg.rfind("--repetitions=", 0) == 0) {
            repetitions = std::max(1, std::stoi(arg.substr(14)));
        } else {
            std::cerr << "usage: encode-lab [--out=DIR] [--repetitions=N]\n";
            return 2;
        }
    }
    std::filesystem::create_directories(out);
    constexpr int kFrames = raster::kAnimationFrameCount;
    std::vector<raster::Framebuffer> frames;
    for (int i = 0; i < kFrames; ++i) {
        frames.emplace_back(raster::kSceneWidth, raster::kSceneHeight);
        raster::render_tumble_frame(frames.back(), i, kFrames, raster::CubeStyle::filled);
    }
    std::vector<Config> all = configs();
    const std::filesystem::path scratch = out / "encode-check.webp";
    for (int r = 0; r < repetitions; ++r) {
        for (Config& c : all) {  // interleaved: every configuration once per round
            // The highest effort takes a minute or more a run: measured in the first round only.
            if (r > 0 && c.settings.effort == raster::Effort::max) continue;
            const auto start = std::chrono::steady_clock::now();
            raster::AnimationEncoder encoder(raster::kSceneWidth, raster::kSceneHeight, raster::kFrameSpacingMs,
                                             c.settings);
            for (const raster::Framebuffer& frame : frames) encoder.add_frame(frame);
            const std::vector<std::uint8_t> bytes = encoder.finish();
            c.seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            c.bytes = bytes.size();
            if (r == 0) {  // lossless, every time: each decoded frame is the rendered one
                std::ofstream(scratch, std::ios::binary)
                    .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
                int index = 0;
                bool exact = true;
                raster::for_each_webp_frame(scratch, [&](const raster::DecodedFrame& decoded) {
                    exact = exact && decoded.image == frames[static_cast<std::size_t>(index++)];
                    return true;
                });
                if (!exact || index != kFrames) {
                    std::cerr << "encode-lab: " << c.name << " does not decode to the frames\n";
                    return 1;
                }
            }
            std::cerr << "encode-lab: round " << r + 1 << ", " << c.name << ": " << c.bytes << " bytes, "
                      << c.seconds.back() << " s\n";
        }
    }
    std::filesystem::remove(scratch);
    // The Pareto front: no other configuration is both faster and smaller.
    std::ofstream csv(out / "encode.csv");
    csv << "name,path,seconds_median,seconds_min,seconds_max,bytes,pareto\n";
    std::ofstream summary(out / "encode-summary.md");
    summary << "| configuration | seconds (median, min-max of " << repetitions
            << "; max effort: one run) | bytes | Pareto |\n|---|---|---|---|\n";
    for (const Config& c : all) {
        const double t = lab::median(c.seconds);
        bool dominated = false;
        for (const Config& o : all) {
            const double u = lab::median(o.seconds);
            if (&o != &c && u <= t && o.bytes <= c.bytes && (u < t || o.bytes < c.bytes)) dominated = true;
        }
        const auto [low, high] = std::minmax_element(c.seconds.begin(), c.seconds.end());
        csv << c.name << ',' << (c.settings.path == raster::AnimationPath::anim ? "anim" : "parallel") << ',' << t
            << ',' << *low << ',' << *high << ',' << c.bytes << ',' << (dominated ? 0 : 1) << '\n';
        char line[200];
        std::snprintf(line, sizeof line, "| %s | %.2f (%.2f-%.2f) | %zu | %s |\n", c.name.c_str(), t, *low, *high,
                      c.bytes, dominated ? "" : "yes");
        summary << line;
    }
    std::cerr << "encode-lab: wrote encode.csv and encode-summary.md in " << out.string() << "\n";
    return 0;
}
