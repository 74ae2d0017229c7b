// Stays whole: the interpolation measure and the summary of all three read top to bottom.
// perspective-lab: the choices of the perspective pipeline measured against exact answers.
//  1. Interpolation: affine (linear on screen) against through 1/w, on a floor seen at grazing
//     angles, as the error of texture coordinates in texels against the ray-cast truth, and time.
//  2. Clipping: all six planes against near and far with a guard band: pixel equality and time.
//  3. Depth: which encodings of depth keep two close surfaces in order as far / near grows.
// Writes perspective-*.csv and perspective-summary.md; lab/perspective_charts.gp draws the charts.
#include "lab_args.hpp"

#include <raster/shade/shaders.hpp>
#include "perspective_clip_depth.hpp"
#include "perspective_floor.hpp"
#include "rasterize/setup_perspective.hpp"
#include "recording_shader.hpp"

#include <raster/geometry/shapes.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace perspective_lab;

constexpr double kTexelsPerUnit = 256.0;  // a 256 x 256 texture repeated once per world unit

std::string number(double v, const char* format) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

// A floor at y = -1 from z = 0.5 to 40 and x = -20 to 20, split into n x n cells, seen from the
// origin looking `degrees` below the horizon: the texture coordinates are world x and z.
raster::Mesh floor_grid(int n) {
    raster::Mesh mesh;
    const float x0 = -20.0F, x1 = 20.0F, z0 = 0.5F, z1 = 40.0F;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(n),
                        v = static_cast<float>(j) / static_cast<float>(n);
            mesh.positions.emplace_back(x0 + (x1 - x0) * u, -1.0F, z0 + (z1 - z0) * v);
            mesh.normals.emplace_back(0.0F, 1.0F, 0.0F);
        }
    }
    const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {  // clockwise seen from above
            mesh.facets.push_back({{at(i, j), at(i, j + 1), at(i + 1, j + 1)}, {0, 1, 0}});
            mesh.facets.push_back({{at(i, j), at(i + 1, j + 1), at(i + 1, j)}, {0, 1, 0}});
        }
    }
    mesh.surface = raster::Surface::smooth;
    mesh.convex = true;
    return mesh;
}

// What a texture lookup costs at least: a checkerboard from the interpolated coordinates.
struct Checkerboard {
    using Varying = glm::vec3;
    static constexpr bool kFacetNormal = false;
    [[nodiscard]] Varying vertex(const raster::Corner& corner) const noexcept { return corner.position; }
    [[nodiscard]] raster::Rgb pixel(const glm::vec3& world) const noexcept {
        const bool dark =
            (static_cast<int>(std::floor(world.x * 8)) + static_cast<int>(std::floor(world.z * 8))) % 2 == 0;
        return dark ? raster::Rgb{40, 40, 40} : raster::Rgb{220, 220, 220};
    }
};

// The mip level a filter would choose at pixel (i, j) from texture coordinate changes per pixel
// step dx and dy (world units): log2 of the longer, in texels.
double mip_level(glm::dvec2 dx, glm::dvec2 dy) {
    return std::log2(std::max(glm::length(dx), glm::length(dy)) * kTexelsPerUnit);
}

// The exact mip level at pixel (i, j), from central differences of the ray-cast floor point.
std::optional<double> exact_mip_level(const raster::PerspectiveCamera& camera, int i, int j) {
    constexpr double h = 1e-3;
    const auto left = floor_at_point(camera, i + 0.5 - h, j + 0.5),
               right = floor_at_point(camera, i + 0.5 + h, j + 0.5);
    const auto above = floor_at_point(camera, i + 0.5, j + 0.5 - h),
               below = floor_at_point(camera, i + 0.5, j + 0.5 + h);
    if (!left || !right || !above || !below) return std::nullopt;
    return mip_level((*right - *left) / (2 * h), (*below - *above) / (2 * h));
}

// Keeps the point and its change per pixel step that every pixel is shaded with, like
// lab::RecordingShader, for a shader that filters.
struct FootprintRecorder {
    using Varying = glm::vec3;
    static constexpr bool kFacetNormal = false;
    std::vector<glm::vec3>* seen;
    std::vector<glm::vec3>* per_x;
    std::vector<glm::vec3>* per_y;
    [[nodiscard]] Varying vertex(const raster::Corner& corner) const noexcept { return corner.position; }
    [[nodiscard]] raster::Rgb pixel(const glm::vec3& world, const glm::vec3& dx, const glm::vec3& dy) const noexcept {
        per_x->push_back(dx), per_y->push_back(dy);
        return lab::RecordingShader{seen}.pixel(world);
    }
};

struct InterpolationRow {
    std::string method;
    int cells;
    double degrees;
    double worst_texels, mean_texels, ms;
    double worst_levels = 0.0, mean_levels = 0.0;            // the mip level from the per-pixel derivatives
    double worst_quad_levels = 0.0, mean_quad_levels = 0.0;  // from differences across 2 x 2 quads, as GPUs take it
};

// Renders the floor and, for every covered pixel, compares the world point its colour came from:
// the framebuffer keeps an index into the points the shader saw, in 24 bits.
// `mode`: affine (screen_linear), through 1/w in double (the product) or in float.
InterpolationRow measure_interpolation(raster::detail::Interpolation mode, int cells, double degrees) {
    using raster::detail::Interpolation;
    const raster::PerspectiveCamera camera = grazing_camera(degrees);
    const raster::Mesh mesh = floor_grid(cells);
    raster::Framebuffer image(kWidth, kHeight);
    std::vector<glm::vec3> seen;
    const auto draw = [&](const auto& shader) {
        using Shader = std::decay_t<decltype(shader)>;
        switch (mode) {
        case Interpolation::screen_linear:
            return raster::detail::draw_facets_in_perspective<Shader, Interpolation::screen_linear>(
                image, nullptr, camera, mesh, shader);
        case Interpolation::perspective:
            return raster::detail::draw_facets_in_perspective<Shader, Interpolation::perspective>(image, nullptr,
                                                                                                  camera, mesh, shader);
        case Interpolation::perspective_float:
            return raster::detail::draw_facets_in_perspective<Shader, Interpolation::perspective_float>(
                image, nullptr, camera, mesh, shader);
        }
        return std::size_t{0};
    };
    image.clear({255, 255, 255});
    std::vector<glm::vec3> per_x, per_y;
    draw(FootprintRecorder{&seen, &per_x, &per_y});
    const char* const method = mode == Interpolation::screen_linear ? "affine"
                               : mode == Interpolation::perspective ? "perspective"
                                                                    : "perspective in float";
    InterpolationRow row{method, cells, degrees, 0.0, 0.0, 0.0};
    // The point pixel (i, j) was shaded with, when the floor covers it.
    const auto seen_at = [&](int i, int j) -> std::optional<glm::dvec2> {
        const std::uint32_t index = lab::recorded_index(image, i, j);
        if (index >= seen.size()) return std::nullopt;
        return glm::dvec2(seen[index].x, seen[index].z);
    };
    long count = 0, levelled = 0, quads = 0;
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            const std::uint32_t index = lab::recorded_index(image, i, j);
            if (index >= seen.size()) continue;  // background
            const std::optional<glm::dvec2> truth = floor_at(camera, i, j);
            if (!truth) continue;
            const double error = glm::distance(glm::dvec2(seen[index].x, seen[index].z), *truth) * kTexelsPerUnit;
            row.worst_texels = std::max(row.worst_texels, error);
            row.mean_texels += error;
            ++count;
            const std::optional<double> exact = exact_mip_level(camera, i, j);
            if (!exact) continue;
            const glm::vec3 dx = per_x[index], dy = per_y[index];
            const double levels = std::abs(mip_level({dx.x, dx.z}, {dy.x, dy.z}) - *exact);
            row.worst_levels = std::max(row.worst_levels, levels);
            row.mean_levels += levels;
            ++levelled;
            // A GPU's level: the differences across the pixel's 2 x 2 quad, where all of it is covered.
            const int qi = i & ~1, qj = j & ~1;
            const auto left = seen_at(qi, j), right = seen_at(qi + 1, j), top = seen_at(i, qj),
                       bottom = seen_at(i, qj + 1);
            if (!left || !right || !top || !bottom) continue;
            const double quad_levels = std::abs(mip_level(*right - *left, *bottom - *top) - *exact);
            row.worst_quad_levels = std::max(row.worst_quad_levels, quad_levels);
            row.mean_quad_levels += quad_levels;
            ++quads;
        }
    }
    row.mean_texels /= static_cast<double>(std::max(count, 1L));
    row.mean_levels /= static_cast<double>(std::max(levelled, 1L));
    row.mean_quad_levels /= static_cast<double>(std::max(quads, 1L));
    // Time: the checkerboard shader, median of 31 frames.
    std::vector<double> times;
    for (int r = 0; r < 31; ++r) {
        const auto start = std::chrono::steady_clock::now();
        draw(Checkerboard{});
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    row.ms = lab::median(times);
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<std::filesystem::path> chosen = lab::out_dir(argc, argv, "perspective-lab");
    if (!chosen) return 2;
    const std::filesystem::path out = *chosen;
    std::filesystem::create_directories(out);

    std::cerr << "perspective-lab: interpolation\n";
    std::vector<InterpolationRow> interpolation;
    for (const double degrees : {5.0, 20.0}) {
        using raster::detail::Interpolation;
        for (const int cells : {1, 2, 4, 8, 16, 32, 64})
            interpolation.push_back(measure_interpolation(Interpolation::screen_linear, cells, degrees));
        for (const Interpolation mode : {Interpolation::perspective, Interpolation::perspective_float}) {
            interpolation.push_back(measure_interpolation(mode, 1, degrees));
            interpolation.push_back(measure_interpolation(mode, 64, degrees));
        }
    }
    std::cerr << "perspective-lab: clipping\n";
    std::vector<ClippingRow> clipping;
    for (const int fov : {40, 90, 150}) {
        for (const std::string_view name : {"point-light", "point-lights"})
            clipping.push_back(measure_clipping(name, fov));
    }
    std::cerr << "perspective-lab: depth\n";
    const std::vector<DepthRow> depth = measure_depth();

    std::ofstream csv(out / "interpolation.csv");
    csv << "method,cells,degrees,worst_texels,mean_texels,ms,worst_levels,mean_levels,worst_quad_levels,mean_quad_levels\n";
    for (const InterpolationRow& r : interpolation) {
        csv << r.method << ',' << r.cells << ',' << r.degrees << ',' << r.worst_texels << ',' << r.mean_texels << ','
            << r.ms << ',' << r.worst_levels << ',' << r.mean_levels << ',' << r.worst_quad_levels << ','
            << r.mean_quad_levels << '\n';
    }
    std::ofstream depth_csv(out / "depth-perspective.csv");
    depth_csv << "ratio";
    for (const DepthEncoding& e : encodings()) depth_csv << ',' << e.name;
    depth_csv << '\n';
    for (std::size_t k = 0; k < depth.size(); k += encodings().size()) {
        depth_csv << depth[k].ratio;
        for (std::size_t e = 0; e < encodings().size(); ++e) {
            const DepthRow& r = depth[k + e];
            depth_csv << ',' << static_cast<double>(r.wrong) / static_cast<double>(std::max(r.compared, 1L));
        }
        depth_csv << '\n';
    }

    std::ofstream summary(out / "perspective-summary.md");
    summary
        << "# Perspective summary\n\nWritten by `perspective-lab` (`tools/bootstrap.sh lab`), " << kWidth << " x "
        << kHeight
        << ".\n\n## Interpolation\n\nA floor 40 x 39.5 units (y = -1) seen from 1 above, looking 5 or 20 degrees down, "
        << "60-degree field of view; texture coordinates are world x and z at 256 texels per unit. Error: distance "
        << "between the coordinates a pixel is shaded with and where its line of sight meets the floor; mip levels: "
        << "how far the level chosen from the coordinates' change per pixel (log2 of the longer step, in texels) is "
        << "from the exact one (central differences of the ray cast), for the product's analytic derivatives and for "
        << "a GPU's differences across 2 x 2 quads of the shaded points. Time: median of 31 frames with a checkerboard "
        << "shader.\n\n| method | cells | looking down | worst (texels) | mean (texels) | worst (mip levels) | mean (mip levels) "
        << "| quads: worst (mip levels) | quads: mean (mip levels) | ms |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const InterpolationRow& r : interpolation) {
        summary << "| " << r.method << " | " << r.cells << " x " << r.cells << " | " << r.degrees << " deg | "
                << number(r.worst_texels, "%.3f") << " | " << number(r.mean_texels, "%.3f") << " | "
                << number(r.worst_levels, "%.4f") << " | " << number(r.mean_levels, "%.5f") << " | "
                << number(r.worst_quad_levels, "%.4f") << " | " << number(r.mean_quad_levels, "%.5f") << " | "
                << number(r.ms, "%.2f") << " |\n";
    }
    summary
        << "\n## Clipping\n\nThe scene's still through `--perspective FOV`, Phong-shaded, depth-tested; all six planes "
        << "(x and y clipped at the image) against near and far with the guard band (product). Time: median of 31 "
        << "interleaved frames.\n\n| scene | fov | pixels that differ | six planes (ms) | guard band (ms) |\n|---|---|---|---|---|\n";
    for (const ClippingRow& r : clipping) {
        summary << "| " << r.scene << " | " << r.fov << " | " << r.differing << " | " << number(r.six_plane_ms, "%.2f")
                << " | " << number(r.guard_band_ms, "%.2f") << " |\n";
    }
    summary
        << "\n## Depth\n\nTwo floors 1e-5 apart (relative), the nearer at y = -1, seen from the origin looking 10 degrees "
        << "down, far = 1000; share of compared pixels where the encoding does not keep the nearer floor in front.\n\n| far / near |";
    for (const DepthEncoding& e : encodings()) summary << ' ' << e.name << " |";
    summary << "\n|---|";
    for (std::size_t e = 0; e < encodings().size(); ++e) summary << "---|";
    summary << '\n';
    for (std::size_t k = 0; k < depth.size(); k += encodings().size()) {
        summary << "| " << number(depth[k].ratio, "%.0e") << " |";
        for (std::size_t e = 0; e < encodings().size(); ++e) {
            const DepthRow& r = depth[k + e];
            summary << ' '
                    << number(100.0 * static_cast<double>(r.wrong) / static_cast<double>(std::max(r.compared, 1L)),
                              "%.2f")
                    << " % |";
        }
        summary << '\n';
    }
    std::cerr << "perspective-lab: wrote interpolation.csv, depth-perspective.csv and perspective-summary.md in "
              << out.string() << "\n";
    return 0;
}
