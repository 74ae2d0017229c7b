// One lab program feeding one set of tables; stays whole so that it reads top to bottom.
// antialias-lab: how far each anti-aliasing method's coverage is from the exact area of every
// pixel, and what it costs per frame. The product's --samples 1..16 draws white triangles on
// black (unlit, so a pixel's linear value is its coverage estimate), by multisampling and by
// supersampling (whose coverage must be the same); the exact area comes from
// clipping each triangle to each pixel's square in double precision. A lab-only method, analytic
// coverage composited with "over", shows where per-triangle areas fail: edges two triangles share.
// Writes antialias.csv (error by case and method), antialias-time.csv (time per frame of two
// scenes beside each case's mean error) and antialias-summary.md; lab/antialias_chart.gp draws antialias.svg.
#include "lab_args.hpp"

#include <raster/geometry/mesh.hpp>
#include <raster/image/colour.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using Triangle = std::array<glm::dvec2, 3>;  // screen pixels, centres on whole numbers, y down

constexpr int kSide = 48;  // each frame is kSide x kSide pixels

// One case of the corpus: frames, each a few triangles that never overlap.
struct Case {
    std::string name;
    std::vector<std::vector<Triangle>> frames;
};

// A position on raster's 1/256-pixel grid, so the product's snapping keeps it exactly.
double on_grid(double v) { return std::round(v * 256.0) / 256.0; }

double twice_area(const Triangle& t) {
    return (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
}

// The area of a convex polygon inside the pixel square centred on (px, py): Sutherland-Hodgman
// against the square's four sides, then the shoelace formula.
double area_in_pixel(const std::vector<glm::dvec2>& polygon, int px, int py) {
    std::vector<glm::dvec2> current = polygon, next;
    const double bounds[4] = {px - 0.5, px + 0.5, py - 0.5, py + 0.5};
    for (int side = 0; side < 4; ++side) {
        next.clear();
        const auto inside = [&](glm::dvec2 p) {
            switch (side) {
            case 0: return p.x >= bounds[0];
            case 1: return p.x <= bounds[1];
            case 2: return p.y >= bounds[2];
            default: return p.y <= bounds[3];
            }
        };
        const auto cut = [&](glm::dvec2 a, glm::dvec2 b) {
            const double edge = bounds[side];
            const double t = side < 2 ? (edge - a.x) / (b.x - a.x) : (edge - a.y) / (b.y - a.y);
            return a + (b - a) * t;
        };
        for (std::size_t i = 0; i < current.size(); ++i) {
            const glm::dvec2 a = current[i], b = current[(i + 1) % current.size()];
            if (inside(a)) {
                next.push_back(a);
                if (!inside(b)) next.push_back(cut(a, b));
            } else if (inside(b)) {
                next.push_back(cut(a, b));
            }
        }
        current.swap(next);
        if (current.empty()) return 0.0;
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < current.size(); ++i) {
        const glm::dvec2 a = current[i], b = current[(i + 1) % current.size()];
        sum += a.x * b.y - b.x * a.y;
    }
    return std::abs(sum) / 2.0;
}

// Per pixel, each triangle's exact area in it (row-major), for the reference and the analytic method.
std::vector<std::vector<double>> areas_of(const std::vector<Triangle>& frame) {
    std::vector<std::vector<double>> areas;
    for (const Triangle& t : frame) {
        std::vector<double> area(kSide * kSide, 0.0);
        const int x0 = std::max(0, static_cast<int>(std::floor(std::min({t[0].x, t[1].x, t[2].x}))));
        const int x1 = std::min(kSide - 1, static_cast<int>(std::ceil(std::max({t[0].x, t[1].x, t[2].x}))));
        const int y0 = std::max(0, static_cast<int>(std::floor(std::min({t[0].y, t[1].y, t[2].y}))));
        const int y1 = std::min(kSide - 1, static_cast<int>(std::ceil(std::max({t[0].y, t[1].y, t[2].y}))));
        const std::vector<glm::dvec2> polygon(t.begin(), t.end());
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) area[static_cast<std::size_t>(y * kSide + x)] = area_in_pixel(polygon, x, y);
        }
        areas.push_back(std::move(area));
    }
    return areas;
}

// The product's estimate: the triangles drawn white on black, unlit, at `samples` per pixel.
std::vector<double> sampled(const std::vector<Triangle>& frame, int samples, bool every = false) {
    auto mesh = std::make_shared<raster::Mesh>();
    const double centre = (kSide - 1) / 2.0, scale = (kSide - 1) / 2.0;  // OrthoCamera's map for a square image
    for (const Triangle& t : frame) {
        const auto first = static_cast<std::uint32_t>(mesh->positions.size());
        for (const glm::dvec2 p : t) mesh->positions.emplace_back((p.x - centre) / scale, (centre - p.y) / scale, 0.0F);
        mesh->facets.push_back(
            raster::facet_facing_away(mesh->positions, first, first + 1, first + 2, {0.0F, 0.0F, 1.0F}));
    }
    mesh->normals.assign(mesh->positions.size(), {0.0F, 0.0F, -1.0F});
    raster::Scene scene{raster::OrthoCamera(kSide, kSide), {0, 0, 0}, {}, {}, {}};
    scene.objects.push_back({mesh, glm::mat4(1.0F), raster::LinearMaterial{{0, 0, 0}, {1, 1, 1}, {0, 0, 0}, {}},
                             raster::ShadingMethod::unlit});
    raster::Framebuffer image(kSide, kSide);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, {1, samples, every});
    std::vector<double> coverage(kSide * kSide);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x)
            coverage[static_cast<std::size_t>(y * kSide + x)] =
                raster::linear_from_srgb_channel(image.pixel(x, y).g / 255.0);
    }
    return coverage;
}

// Analytic coverage: each triangle's exact area in the pixel, composited over what is there.
std::vector<double> analytic_over(const std::vector<std::vector<double>>& areas) {
    std::vector<double> coverage(kSide * kSide, 0.0);
    for (const auto& area : areas) {
        for (std::size_t i = 0; i < coverage.size(); ++i) coverage[i] += (1.0 - coverage[i]) * area[i];
    }
    return coverage;
}

Triangle random_triangle(std::mt19937& random, double size, double min_area) {
    std::uniform_real_distribution<double> where(4.0, kSide - 5.0), offset(-size / 2, size / 2);
    for (;;) {
        const glm::dvec2 middle(where(random), where(random));
        Triangle t;
        for (glm::dvec2& p : t)
            p = glm::dvec2(on_grid(std::clamp(middle.x + offset(random), 1.0, kSide - 2.0)),
                           on_grid(std::clamp(middle.y + offset(random), 1.0, kSide - 2.0)));
        if (std::abs(twice_area(t)) / 2 >= min_area) return t;
    }
}

std::vector<Case> corpus() {
    std::mt19937 random(20261125);
    std::vector<Case> cases;
    for (const double size : {2.0, 8.0, 32.0}) {
        Case c{"triangles " + std::to_string(static_cast<int>(size)) + " px", {}};
        for (int i = 0; i < 150; ++i) c.frames.push_back({random_triangle(random, size, size * size / 50)});
        cases.push_back(std::move(c));
    }
    // A jittered grid of quads, each cut in two: every inner edge is shared by two triangles.
    Case mesh{"shared edges", {}};
    std::uniform_real_distribution<double> jitter(-1.2, 1.2);
    for (int f = 0; f < 40; ++f) {
        constexpr std::size_t kCells = 6;
        const double cell = (kSide - 8.0) / kCells;
        std::vector<std::vector<glm::dvec2>> grid(kCells + 1, std::vector<glm::dvec2>(kCells + 1));
        for (std::size_t j = 0; j <= kCells; ++j) {
            for (std::size_t i = 0; i <= kCells; ++i) {
                const bool border = i == 0 || j == 0 || i == kCells || j == kCells;
                grid[j][i] = {on_grid(4.3 + static_cast<double>(i) * cell + (border ? 0.0 : jitter(random))),
                              on_grid(4.3 + static_cast<double>(j) * cell + (border ? 0.0 : jitter(random)))};
            }
        }
        std::vector<Triangle> frame;
        for (std::size_t j = 0; j < kCells; ++j) {
            for (std::size_t i = 0; i < kCells; ++i) {
                frame.push_back({grid[j][i], grid[j][i + 1], grid[j + 1][i + 1]});
                frame.push_back({grid[j][i], grid[j + 1][i + 1], grid[j + 1][i]});
            }
        }
        mesh.frames.push_back(std::move(frame));
    }
    cases.push_back(std::move(mesh));
    // Slivers: 30 px long, a tenth to a half of a pixel wide.
    Case slivers{"slivers", {}};
    std::uniform_real_distribution<double> angle(0.0, 3.14159265), width(0.1, 0.5);
    for (int f = 0; f < 150; ++f) {
        const double a = angle(random), w = width(random);
        const glm::dvec2 middle(kSide / 2.0 + jitter(random), kSide / 2.0 + jitter(random));
        const glm::dvec2 along(std::cos(a) * 15.0, std::sin(a) * 15.0), across(-std::sin(a) * w, std::cos(a) * w);
        const auto snapped = [](glm::dvec2 p) { return glm::dvec2(on_grid(p.x), on_grid(p.y)); };
        slivers.frames.push_back({{snapped(middle - along), snapped(middle + along), snapped(middle + across)}});
    }
    cases.push_back(std::move(slivers));
    Case tiny{"sub-pixel", {}};
    for (int f = 0; f < 300; ++f) tiny.frames.push_back({random_triangle(random, 1.0, 0.02)});
    cases.push_back(std::move(tiny));
    return cases;
}

struct Error {
    double sum = 0.0;  // over edge pixels
    double worst = 0.0;
    long pixels = 0;
};

// Edge pixels are those some triangle covers in part: an edge crosses them, shared or not.
std::vector<bool> edge_pixels(const std::vector<std::vector<double>>& areas) {
    std::vector<bool> edge(kSide * kSide, false);
    for (const auto& area : areas) {
        for (std::size_t i = 0; i < edge.size(); ++i) edge[i] = edge[i] || (area[i] > 1e-9 && area[i] < 1.0 - 1e-9);
    }
    return edge;
}

void measure(Error& error, const std::vector<double>& estimate, const std::vector<double>& exact,
             const std::vector<bool>& edge) {
    for (std::size_t i = 0; i < exact.size(); ++i) {
        const double e = std::abs(estimate[i] - exact[i]);
        error.worst = std::max(error.worst, e);
        if (edge[i]) {
            error.sum += e;
            ++error.pixels;
        }
    }
}

// Median milliseconds per frame of a scene at each sample count, multisampled then supersampled,
// everything interleaved; one Renderer per configuration, kept as an animation keeps it.
template <typename Scene>
std::vector<double> times(const Scene& scene, int repetitions) {
    std::vector<raster::Renderer> renderers;
    for (const bool every : {false, true}) {
        for (const int samples : raster::kSampleCounts)
            renderers.emplace_back(raster::RenderOptions{1, samples, every});
    }
    raster::Framebuffer frame(800, 600);
    std::vector<std::vector<double>> seconds(renderers.size());
    for (int r = 0; r < repetitions; ++r) {
        for (std::size_t k = 0; k < renderers.size(); ++k) {
            const auto start = std::chrono::steady_clock::now();
            renderers[k].render(frame, scene);
            seconds[k].push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
    }
    std::vector<double> medians;
    for (auto& s : seconds) medians.push_back(lab::median(s));
    return medians;
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = lab::out_dir(argc, argv, "antialias-lab");
    if (!out) return 2;
    std::filesystem::create_directories(*out);
    std::ofstream table(*out / "antialias.csv");
    table << "case,method,samples,mean edge error,worst error,edge pixels\n";
    std::ofstream summary(*out / "antialias-summary.md");
    summary << "| case | method | mean error over edge pixels | worst error |\n|---|---|---|---|\n";
    std::vector<std::string> names;
    std::vector<std::vector<double>> means;  // by case, then by sample count
    for (const Case& c : corpus()) {
        std::vector<Error> errors(std::size(raster::kSampleCounts) + 1);
        for (const auto& frame : c.frames) {
            const auto areas = areas_of(frame);
            std::vector<double> exact(kSide * kSide, 0.0);
            for (const auto& area : areas) {
                for (std::size_t i = 0; i < exact.size(); ++i) exact[i] += area[i];
            }
            for (double& e : exact) e = std::min(e, 1.0);
            const std::vector<bool> edge = edge_pixels(areas);
            for (std::size_t k = 0; k < std::size(raster::kSampleCounts); ++k) {
                const std::vector<double> multisampled = sampled(frame, raster::kSampleCounts[k]);
                if (multisampled != sampled(frame, raster::kSampleCounts[k], true)) {
                    std::cerr << "antialias-lab: multisampling and supersampling cover " << c.name << " differently\n";
                    return 1;
                }
                measure(errors[k], multisampled, exact, edge);
            }
            measure(errors.back(), analytic_over(areas), exact, edge);
        }
        names.push_back(c.name);
        means.emplace_back();
        for (std::size_t k = 0; k < errors.size(); ++k) {
            const bool analytic = k == errors.size() - 1;
            const std::string method =
                analytic ? "analytic over" : std::to_string(raster::kSampleCounts[k]) + " samples";
            const double mean = errors[k].sum / static_cast<double>(std::max(errors[k].pixels, 1L));
            if (!analytic) means.back().push_back(mean);
            table << c.name << ',' << method << ',' << (analytic ? 0 : raster::kSampleCounts[k]) << ',' << mean << ','
                  << errors[k].worst << ',' << errors[k].pixels << '\n';
            char row[160];
            std::snprintf(row, sizeof row, "| %s | %s | %.4f | %.3f |\n", c.name.c_str(), method.c_str(), mean,
                          errors[k].worst);
            summary << row;
        }
        std::cout << "antialias-lab: " << c.name << " measured\n";
    }

    // The cost: one thread, 800 x 600, the diary's torus (Phong, lit) and Ptah's textured knot.
    const auto torus_ms = times(raster::DiaryScene("torus").still(800, 600), 9);
    const auto ptah_ms = times(raster::SeedScene("ptah").still(800, 600), 9);
    const std::size_t counts = std::size(raster::kSampleCounts);
    std::ofstream timing(*out / "antialias-time.csv");
    timing << "samples,torus ms,ptah ms,torus supersampled ms,ptah supersampled ms";
    for (const std::string& name : names) timing << ',' << name;
    timing << '\n';
    summary
        << "\n| samples | torus, ms per 800 x 600 frame | supersampled | ptah, ms | supersampled |\n|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < counts; ++k) {
        timing << raster::kSampleCounts[k] << ',' << torus_ms[k] << ',' << ptah_ms[k] << ',' << torus_ms[counts + k]
               << ',' << ptah_ms[counts + k];
        for (const auto& by_count : means) timing << ',' << by_count[k];
        timing << '\n';
        char row[160];
        std::snprintf(row, sizeof row, "| %d | %.1f | %.1f | %.1f | %.1f |\n", raster::kSampleCounts[k], torus_ms[k],
                      torus_ms[counts + k], ptah_ms[k], ptah_ms[counts + k]);
        summary << row;
    }
    std::cout << "antialias-lab: wrote " << (*out / "antialias.csv").string() << '\n';
    return 0;
}
