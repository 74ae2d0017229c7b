// raster-bench: the original's baseline benchmarks (its "performance-eval") re-run here: the
// 0.0.17 torus tumble, 360 frames rendered in memory and not encoded, at five mesh details and
// five image sizes. Prints both tables with the original's published numbers beside ours, and a
// third of ours: every torus scene at its own detail, Phase 1 against Phase 2's linear light.
#include <raster/geometry/shapes.hpp>
#include <raster/platform/cores.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>
#include "command_line.hpp"
#include "help_format.hpp"
#include "option_checks.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <sys/utsname.h>
#include <unistd.h>

namespace {

struct Case {
    std::string table;  // "detail" or "resolution"
    int detail;         // torus(24 * detail, 16 * detail)
    int width;
    int height;
    double original_fps;          // the original's published figure (macOS, machine not stated); 0: none
    std::string scene = "torus";  // the "scenes" table renders each scene's own meshes
    int fov = 0;                  // and, when not 0, through this pinhole (--perspective)
    std::vector<double> fps{};
};

std::vector<Case> cases() {
    return {{"detail", 1, 800, 600, 659.08},
            {"detail", 2, 800, 600, 544.20},
            {"detail", 4, 800, 600, 361.44},
            {"detail", 8, 800, 600, 184.38},
            {"detail", 16, 800, 600, 77.68},
            {"resolution", 1, 800, 600, 704.76},
            {"resolution", 1, 1280, 720, 502.97},
            {"resolution", 1, 1920, 1080, 244.07},
            {"resolution", 1, 3840, 2160, 65.38},
            {"resolution", 1, 7680, 4320, 16.65},
            {"scenes", 2, 800, 600, 0.0, "torus"},
            {"scenes", 2, 800, 600, 0.0, "materials"},
            {"scenes", 2, 800, 600, 0.0, "three-lights"},
            {"scenes", 2, 800, 600, 0.0, "point-lights"},
            {"scenes", 2, 800, 600, 0.0, "shaders"},
            {"scenes", 2, 800, 600, 0.0, "torus", 60},
            {"scenes", 2, 800, 600, 0.0, "point-lights", 60},
            {"scenes", 2, 800, 600, 0.0, "ptah"},
            {"scenes", 2, 800, 600, 0.0, "flythrough"},
            {"scenes", 2, 800, 600, 0.0, "islands"}};
}

// Frames per second for `frames` frames of the torus tumble at this case's detail and size.
double measure(const Case& c, int frames) {
    if (raster::is_seed_scene(c.scene)) {  // the other seeds' scenes bring their own cameras
        const raster::SeedScene seed(c.scene);
        raster::Framebuffer image(c.width, c.height);
        raster::DepthBuffer depth;
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < frames; ++i) raster::render(image, seed.frame(c.width, c.height, i, frames), depth);
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        return frames / elapsed.count();
    }
    const raster::DiaryScene torus(c.scene);
    const auto mesh = std::make_shared<const raster::Mesh>(raster::torus(24 * c.detail, 16 * c.detail));
    raster::Framebuffer image(c.width, c.height);
    raster::DepthBuffer depth;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < frames; ++i) {
        raster::Scene scene = torus.frame(c.width, c.height, i, frames);
        if (c.table != "scenes") scene.objects.front().mesh = mesh;
        if (c.fov == 0) {
            raster::render(image, scene, depth);
        } else {
            raster::render(image, raster::in_perspective(scene, c.width, c.height, c.fov), depth);
        }
    }
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    return frames / elapsed.count();
}

// The vertices and facets a case draws: the original's torus, or all of a scene's objects.
std::pair<std::size_t, std::size_t> drawn_size(const Case& c) {
    if (c.table != "scenes") {
        const auto vertices = static_cast<std::size_t>(24 * 16 * c.detail * c.detail);
        return {vertices, 2 * vertices};
    }
    std::pair<std::size_t, std::size_t> size{0, 0};
    const std::vector<raster::SceneObject> objects =
        raster::is_seed_scene(c.scene) ? raster::SeedScene(c.scene).frame(c.width, c.height, 0, 1).objects
                                       : raster::DiaryScene(c.scene).frame(c.width, c.height, 0, 1).objects;
    for (const raster::SceneObject& object : objects) {
        size.first += object.mesh->positions.size();
        size.second += object.mesh->facets.size();
    }
    return size;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

std::string machine() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown processor";
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    }
    utsname system{};
    ::uname(&system);
    return model + ", " + std::to_string(raster::available_cores()) + " logical cores, " + system.sysname + " " +
           system.release + ", compiled by " + __VERSION__;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Times the original's two baseline tables: the 0.0.17 torus tumble rendered in memory "
                 "(no encoding), by mesh detail at 800x600 and by image size at torus(24, 16); then every "
                 "torus scene of Phases 1 and 2, and the seed scenes, at 800x600.",
                 "raster-bench");
    configure_app(app);
    app.footer("Example:\n  raster-bench --repetitions 5 --csv bench.csv   # about 8 minutes on 2 cores");
    int frames = 360;
    int repetitions = 3;
    std::string csv;
    add_integer_option(app, "--frames", frames, 1, 100000, "Frames per measurement, as the original's 360");
    add_integer_option(app, "--repetitions", repetitions, 1, 1000,
                       "Runs of every case, interleaved; the tables show the median and the range");
    app.add_option("--csv", csv, "Also write the measurements as CSV to this file")->option_text("FILE");
    std::string only = "all";
    add_choice_option<std::string>(
        app, "--table", only,
        {{"all", "all"}, {"detail", "detail"}, {"resolution", "resolution"}, {"scenes", "scenes"}},
        "Which table to measure: the original's two, our scenes, or all", "all");
    if (const std::optional<int> exit_code = parse_command_line(app, argc, argv)) return *exit_code;

    if (!csv.empty()) {
        try {
            raster::check_output_path(csv);  // before minutes of work, not after
        } catch (const std::exception& error) {
            std::cerr << "raster-bench: " << error.what() << "\n";
            return 1;
        }
    }
    std::vector<Case> all = cases();
    std::erase_if(all, [&](const Case& c) { return only != "all" && c.table != only; });
    const bool terminal = ::isatty(2) == 1;
    for (int r = 0; r < repetitions; ++r) {
        for (Case& c : all) {
            std::cerr << (terminal ? "\r\033[K" : "") << "raster-bench: run " << (r + 1) << "/" << repetitions << ", "
                      << c.table << " table, " << c.width << "x" << c.height << ", " << c.scene << "(" << 24 * c.detail
                      << ", " << 16 * c.detail << ")" << (terminal ? "" : "\n") << std::flush;
            c.fps.push_back(measure(c, frames));
        }
    }
    if (terminal) std::cerr << "\r\033[K";

    std::ostringstream out;
    out << "Machine: " << machine() << "\n"
        << frames << " frames per run, median of " << repetitions << " interleaved runs (min-max); the original's "
        << "figures are from its benchmarks post (macOS, machine not stated)\n\n";
    const auto has = [&](const char* table) {
        return std::any_of(all.begin(), all.end(), [&](const Case& c) { return c.table == table; });
    };
    if (has("detail")) out << "| Vertices | Facets | FPS (raster) | FPS (original) |\n|---|---|---|---|\n";
    for (const Case& c : all) {
        if (c.table != "detail") continue;
        const int vertices = 24 * 16 * c.detail * c.detail;
        out << "| " << vertices << " | " << 2 * vertices << " | "
            << format("%.1f (%.1f-%.1f)", median(c.fps), *std::min_element(c.fps.begin(), c.fps.end()),
                      *std::max_element(c.fps.begin(), c.fps.end()))
            << " | " << format("%.2f", c.original_fps) << " |\n";
    }
    if (has("resolution")) out << "\n| Dimensions | Pixels | FPS (raster) | FPS (original) |\n|---|---|---|---|\n";
    for (const Case& c : all) {
        if (c.table != "resolution") continue;
        out << "| " << c.width << "x" << c.height << " | " << c.width * c.height << " | "
            << format("%.1f (%.1f-%.1f)", median(c.fps), *std::min_element(c.fps.begin(), c.fps.end()),
                      *std::max_element(c.fps.begin(), c.fps.end()))
            << " | " << format("%.2f", c.original_fps) << " |\n";
    }
    if (has("scenes"))
        out << "\n| Scene (800x600; diary scenes each torus(48, 32)) | Light | FPS (raster) |\n|---|---|---|\n";
    for (const Case& c : all) {
        if (c.table != "scenes") continue;
        out << "| " << c.scene << (c.fov == 0 ? "" : ", --perspective " + std::to_string(c.fov)) << " | "
            << (c.scene == "torus" ? "Phase 1, 8-bit"
                                   : (raster::is_seed_scene(c.scene) ? "linear, textured" : "Phase 2, linear"))
            << " | "
            << format("%.1f (%.1f-%.1f)", median(c.fps), *std::min_element(c.fps.begin(), c.fps.end()),
                      *std::max_element(c.fps.begin(), c.fps.end()))
            << " |\n";
    }
    std::cout << out.str();
    if (!csv.empty()) {
        std::ostringstream table;
        table << "table,scene,fov,vertices,facets,width,height,fps_median,fps_min,fps_max,original_fps\n";
        for (const Case& c : all) {
            const auto [vertices, facets] = drawn_size(c);
            table << c.table << "," << c.scene << "," << c.fov << "," << vertices << "," << facets << "," << c.width
                  << "," << c.height << "," << median(c.fps) << "," << *std::min_element(c.fps.begin(), c.fps.end())
                  << "," << *std::max_element(c.fps.begin(), c.fps.end()) << "," << c.original_fps << "\n";
        }
        const std::string text = table.str();
        try {
            raster::write_output_file(csv, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()),
                                      {});
        } catch (const std::exception& error) {
            std::cerr << "raster-bench: " << error.what() << "\n";
            return 1;
        }
    }
    return 0;
}
