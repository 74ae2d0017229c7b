// Stays whole: one lab program, its scenes, timing and tables read together (doc/lab/README.md#transparency).
// Exact transparency against the cheap methods (doc/conventions.md#transparency): error and time against
// per-object sorting and weighted blended OIT on crossing layers, and the cost of 1 to 8 layers over every
// pixel against the same layers opaque. Writes transparency.csv, transparency-cost.csv and a summary.
#include <raster/image/colour.hpp>
#include <raster/render/scene.hpp>

#include "lab_args.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include <glm/ext/matrix_transform.hpp>

namespace {

// A square of side 2 split into n x n quads, facing the camera (which looks along +z).
std::shared_ptr<const raster::Mesh> grid(int n) {
    auto mesh = std::make_shared<raster::Mesh>();
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            mesh->positions.emplace_back(-1.0F + 2.0F * static_cast<float>(i) / static_cast<float>(n),
                                         -1.0F + 2.0F * static_cast<float>(j) / static_cast<float>(n), 0.0F);
        }
    }
    mesh->normals.assign(mesh->positions.size(), {0.0F, 0.0F, -1.0F});
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    const glm::vec3 behind(0.0F, 0.0F, 1.0F);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            mesh->facets.push_back(
                raster::facet_facing_away(mesh->positions, at(i, j), at(i + 1, j), at(i + 1, j + 1), behind));
            mesh->facets.push_back(
                raster::facet_facing_away(mesh->positions, at(i, j), at(i + 1, j + 1), at(i, j + 1), behind));
        }
    }
    return mesh;
}

raster::Scene layers(int width, int height, bool blended, int count) {
    raster::Scene scene{raster::OrthoCamera(width, height), {20, 20, 28}, {{{0.3F, 0.5F, -1.0F}}}, {}, {}};
    const auto mesh = grid(32);
    for (int k = 0; k < count; ++k) {
        glm::mat4 model(2.0F);  // wider than the view: every pixel sees all eight
        model[3] =
            glm::vec4(0.02F * static_cast<float>(k), 0.01F * static_cast<float>(k), 0.1F * static_cast<float>(k), 1.0F);
        const float t = static_cast<float>(k) / 7.0F;
        raster::SceneObject object{mesh, model,
                                   raster::LinearMaterial{{0, 0, 0}, {t, 1.0F - t, 0.5F}, {0.2F, 0.2F, 0.2F}, 32.0F}};
        if (blended) object.opacity = {raster::AlphaMode::blend, 0.5F, 0.5F};
        scene.objects.push_back(object);
    }
    return scene;
}

// Three unlit squares turned about y so that each crosses the others, half transparent, over grey.
raster::Scene crossing(int size) {
    raster::Scene scene{raster::OrthoCamera(size, size), {128, 128, 128}, {}, {}, {}};
    const auto mesh = grid(4);
    const raster::LinearRgb colours[3] = {{0.9F, 0.1F, 0.1F}, {0.1F, 0.8F, 0.1F}, {0.1F, 0.2F, 0.9F}};
    for (int k = 0; k < 3; ++k) {
        const float turn = -0.8F + 0.8F * static_cast<float>(k);
        const glm::mat4 model =
            glm::scale(glm::rotate(glm::translate(glm::mat4(1.0F), glm::vec3(0.15F * static_cast<float>(k - 1),
                                                                             0.1F * static_cast<float>(k - 1),
                                                                             0.05F * static_cast<float>(k - 1))),
                                   turn, glm::vec3(0, 1, 0)),
                       glm::vec3(0.6F));
        raster::SceneObject object{mesh, model, raster::LinearMaterial{{0, 0, 0}, colours[k], {0, 0, 0}, {}},
                                   raster::ShadingMethod::unlit};
        object.opacity = {raster::AlphaMode::blend, 0.6F, 0.5F};
        scene.objects.push_back(object);
    }
    return scene;
}

struct Layer {
    std::vector<float> colour;  // straight, linear, three a pixel
    std::vector<float> alpha;
    std::vector<float> depth;  // infinite where the layer is absent
    double centre_depth;       // the object's centre, for sorting per object
};

// Each object alone over nothing at one sample: its colour, alpha and depth at every pixel.
std::vector<Layer> layers_of(const raster::Scene& scene, int w, int h) {
    std::vector<Layer> out;
    const std::array<float, 256>& linear = raster::linear_from_srgb_bytes();
    for (const raster::SceneObject& object : scene.objects) {
        raster::Scene alone = scene;
        alone.objects = {object};
        alone.keep_depth = true;
        raster::Renderer renderer;
        raster::Framebuffer image(w, h);
        renderer.render(image, alone);
        const std::vector<std::uint8_t> alpha = renderer.coverage();
        Layer layer;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const raster::Rgb c = image.pixel(x, y);
                layer.colour.insert(layer.colour.end(), {linear[c.r], linear[c.g], linear[c.b]});
                const auto i = static_cast<std::size_t>(y * w + x);
                layer.alpha.push_back(static_cast<float>(alpha[i]) / 255.0F);
                layer.depth.push_back(renderer.depth().at(x, y));
            }
        }
        layer.centre_depth = static_cast<double>(object.model[3][2]);
        out.push_back(std::move(layer));
    }
    return out;
}

// The mean and largest difference of two linear images, three floats a pixel.
std::pair<double, double> error_of(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0, most = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i]));
        sum += d, most = std::max(most, d);
    }
    return {sum / static_cast<double>(a.size()), most};
}

// The median wall and process (all threads) milliseconds of a frame.
struct Times {
    double wall_ms;
    double cpu_ms;
};

double cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Runs each job in turn `frames` times, interleaved so that a shared machine's load falls on all alike.
std::vector<Times> interleaved(const std::vector<std::function<void()>>& jobs, int frames) {
    std::vector<std::vector<double>> wall(jobs.size()), cpu(jobs.size());
    for (const auto& job : jobs) job();  // warm: memory and threads in place
    for (int frame = 0; frame < frames; ++frame) {
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const auto start = std::chrono::steady_clock::now();
            const double cpu_start = cpu_seconds();
            jobs[j]();
            cpu[j].push_back((cpu_seconds() - cpu_start) * 1e3);
            wall[j].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() * 1e3);
        }
    }
    std::vector<Times> out;
    for (std::size_t j = 0; j < jobs.size(); ++j) out.push_back({lab::median(wall[j]), lab::median(cpu[j])});
    return out;
}

struct MethodRow {
    const char* name;
    double ms;  // CPU: the product's frame, or the layers shaded far to near plus the method's compositing
    double mean_error;
    double max_error;
};

// Error against the exact frame, and cost, of each method on the crossing squares.
std::vector<MethodRow> compare_methods(int frames) {
    constexpr int kSize = 512;
    const raster::Scene scene = crossing(kSize);
    raster::Framebuffer exact_image(kSize, kSize);
    raster::Renderer renderer;
    renderer.render(exact_image, scene);
    const std::array<float, 256>& linear = raster::linear_from_srgb_bytes();
    const auto pixels = static_cast<std::size_t>(kSize) * static_cast<std::size_t>(kSize);
    std::vector<float> exact(pixels * 3);
    for (std::size_t i = 0; i < pixels * 3; ++i) exact[i] = linear[exact_image.bytes()[i]];
    std::vector<Layer> layers = layers_of(scene, kSize, kSize);
    const float grey = linear[128];
    std::vector<std::size_t> order(layers.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return layers[a].centre_depth > layers[b].centre_depth; });
    std::vector<float> sorted(pixels * 3), weighted(pixels * 3);
    // Per-object sorting: whole objects far to near by their centres, each over the result so far.
    const auto sort_per_object = [&] {
        std::fill(sorted.begin(), sorted.end(), grey);
        for (const std::size_t k : order) {
            for (std::size_t i = 0; i < pixels; ++i) {
                const float a = layers[k].alpha[i];
                for (std::size_t c = 0; c < 3; ++c)
                    sorted[i * 3 + c] = a * layers[k].colour[i * 3 + c] + (1.0F - a) * sorted[i * 3 + c];
            }
        }
    };
    // Weighted blended OIT (McGuire and Bavoil 2013, their depth weight for view depths near 1).
    const auto blend_weighted = [&] {
        for (std::size_t i = 0; i < pixels; ++i) {
            double accum[4] = {0, 0, 0, 0}, revealage = 1.0;
            for (const Layer& layer : layers) {
                const double a = layer.alpha[i];
                if (a <= 0.0) continue;
                const double z = layer.depth[i];
                const double w =
                    a * std::clamp(10.0 / (1e-5 + std::pow(z / 5.0, 2.0) + std::pow(z / 200.0, 6.0)), 1e-2, 3e3);
                for (std::size_t c = 0; c < 3; ++c) accum[c] += layer.colour[i * 3 + c] * a * w;
                accum[3] += a * w;
                revealage *= 1.0 - a;
            }
            for (std::size_t c = 0; c < 3; ++c) {
                const double mean = accum[3] > 0.0 ? accum[c] / accum[3] : 0.0;
                weighted[i * 3 + c] = static_cast<float>(mean * (1.0 - revealage) + grey * revealage);
            }
        }
    };
    // What both cheap methods shade: every layer at every pixel it covers, drawn opaque far to near.
    raster::Scene painted = scene;
    painted.objects.clear();
    for (const std::size_t k : order) {
        painted.objects.push_back(scene.objects[k]);
        painted.objects.back().opacity = {};
    }
    raster::Renderer painter({.depth_first = raster::RenderOptions::DepthFirst::never});
    raster::Framebuffer image(kSize, kSize);
    const std::vector<Times> times =
        interleaved({[&] { renderer.render(image, scene); }, [&] { painter.render(image, painted); }, sort_per_object,
                     blend_weighted},
                    frames);
    std::vector<MethodRow> rows;
    const auto row = [&](const char* name, double ms, const std::vector<float>& result) {
        const auto [mean, most] = error_of(result, exact);
        rows.push_back({name, ms, mean, most});
    };
    row("exact", times[0].cpu_ms, exact);
    row("per_object_sorted", times[1].cpu_ms + times[2].cpu_ms, sorted);
    row("weighted_blended", times[1].cpu_ms + times[3].cpu_ms, weighted);
    return rows;
}

struct CostRow {
    int samples, threads, layers;
    Times opaque, every_layer, blended;
};

// `count` lit layers over every pixel of a frame, blended, against the same opaque as drawn (the depth pass shades
// only the nearest) and opaque far to near without the depth pass (every layer shaded: what any blending must shade).
CostRow cost(int samples, int threads, int count, int frames) {
    constexpr int kWidth = 800, kHeight = 600;
    raster::Renderer renderer({.threads = threads, .samples = samples});
    raster::Renderer painter(
        {.threads = threads, .samples = samples, .depth_first = raster::RenderOptions::DepthFirst::never});
    raster::Framebuffer image(kWidth, kHeight);
    const raster::Scene opaque = layers(kWidth, kHeight, false, count), blended = layers(kWidth, kHeight, true, count);
    raster::Scene far_to_near = opaque;
    std::reverse(far_to_near.objects.begin(), far_to_near.objects.end());
    const std::vector<Times> times =
        interleaved({[&] { renderer.render(image, opaque); }, [&] { painter.render(image, far_to_near); },
                     [&] { renderer.render(image, blended); }},
                    frames);
    return {samples, threads, count, times[0], times[1], times[2]};
}

struct Options {
    std::filesystem::path out = "doc/lab";
    int frames = 9;
    bool cost_only = false;  // the cost table alone, on stdout: to compare two builds
    std::vector<int> samples{1, 4}, threads{1, 2}, layers{1, 2, 3, 4, 5, 6, 7, 8};
};

std::optional<Options> options_of(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&](const char* name) {
            return arg.rfind(name, 0) == 0 ? arg.substr(std::strlen(name)) : "";
        };
        if (!value("--out=").empty()) {
            options.out = value("--out=");
        } else if (!value("--frames=").empty()) {
            options.frames = std::max(1, std::atoi(value("--frames=").c_str()));
        } else if (!value("--samples=").empty()) {
            options.samples = {std::atoi(value("--samples=").c_str())};
        } else if (!value("--threads=").empty()) {
            options.threads = {std::atoi(value("--threads=").c_str())};
        } else if (!value("--layers=").empty()) {
            options.layers = {std::clamp(std::atoi(value("--layers=").c_str()), 1, 8)};
        } else if (arg == "--cost") {
            options.cost_only = true;
        } else {
            std::cerr << "usage: transparency-lab [--out=DIR] [--frames=N] [--cost [--samples=S] [--threads=T] "
                         "[--layers=L]]\n";
            return std::nullopt;
        }
    }
    return options;
}
}  // namespace

int main(int argc, char** argv) {
    const std::optional<Options> options = options_of(argc, argv);
    if (!options) return 2;
    std::vector<CostRow> costs;
    std::ostringstream table;
    table << "samples,threads,layers,opaque_ms,every_layer_shaded_ms,blended_ms,ratio,opaque_cpu_ms,blended_cpu_ms,"
             "cpu_ratio,every_layer_shaded_cpu_ms\n";
    for (const int samples : options->samples) {
        for (const int threads : options->threads) {
            // Eight layers on every thread count; the others at one thread, where times are steadiest.
            for (const int count : options->layers) {
                if (threads != 1 && count != 8 && !options->cost_only) continue;
                const CostRow c = cost(samples, threads, count, options->frames);
                costs.push_back(c);
                table << std::fixed << std::setprecision(2) << c.samples << ',' << c.threads << ',' << c.layers << ','
                      << c.opaque.wall_ms << ',' << c.every_layer.wall_ms << ',' << c.blended.wall_ms << ','
                      << c.blended.wall_ms / c.opaque.wall_ms << ',' << c.opaque.cpu_ms << ',' << c.blended.cpu_ms
                      << ',' << c.blended.cpu_ms / c.opaque.cpu_ms << ',' << c.every_layer.cpu_ms << '\n';
                if (options->cost_only) std::cout << table.str() << std::flush, table.str("");
            }
        }
    }
    if (options->cost_only) return 0;
    const std::vector<MethodRow> methods = compare_methods(options->frames);
    std::ofstream(options->out / "transparency-cost.csv") << table.str();
    std::ofstream csv(options->out / "transparency.csv");
    csv << "method,ms,mean_error,max_error\n";
    for (const MethodRow& m : methods)
        csv << m.name << ',' << m.ms << ',' << m.mean_error << ',' << m.max_error << '\n';
    std::ofstream md(options->out / "transparency-summary.md");
    md << "# Exact transparency against the cheap methods\n\nThree unlit squares of alpha 0.6 crossing each other, "
          "512 x 512 at one sample, over grey; errors in linear light against the exact frame. Exact: the product's "
          "frame; the cheap methods: the same layers drawn opaque far to near (every layer shaded where it shows) "
          "plus their compositing; process CPU milliseconds, medians of "
       << options->frames << " interleaved frames.\n\n| method | CPU ms | mean error | worst |\n|---|---|---|---|\n";
    for (const MethodRow& m : methods)
        md << "| " << m.name << " | " << m.ms << " | " << m.mean_error << " | " << m.max_error << " |\n";
    md << "\nCost: 1 to 8 lit layers of 2,048 triangles over every pixel of 800 x 600, blended at alpha 0.5, against "
          "the same opaque as drawn (depth pass first: the nearest layer alone shaded) and opaque far to near without "
          "the depth pass (every layer shaded, as any blending must); medians of "
       << options->frames
       << " interleaved frames, process CPU milliseconds (all threads), the wall-clock ratio beside.\n\n| samples | "
          "threads | layers | opaque | every layer shaded | blended | blended / opaque | every layer / opaque | "
          "wall ratio |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const CostRow& c : costs) {
        md << "| " << c.samples << " | " << c.threads << " | " << c.layers << " | " << c.opaque.cpu_ms << " | "
           << c.every_layer.cpu_ms << " | " << c.blended.cpu_ms << " | " << c.blended.cpu_ms / c.opaque.cpu_ms << " | "
           << c.every_layer.cpu_ms / c.opaque.cpu_ms << " | " << c.blended.wall_ms / c.opaque.wall_ms << " |\n";
    }
    std::cout << table.str();
    for (const MethodRow& m : methods)
        std::cout << m.name << ": " << m.ms << " ms, mean error " << m.mean_error << ", worst " << m.max_error << '\n';
    return 0;
}
