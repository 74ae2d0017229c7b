#include "exact_surface.hpp"
#include "scene_lab.hpp"

#include <raster/geometry/analytic_shape.hpp>
#include <raster/render/auto_detail.hpp>
#include <raster/scenes/diary_scenes.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace lab {
namespace {

constexpr raster::Rgb kNoSurface{255, 0, 255};  // no shading of a blue surface reaches it
constexpr int kWidth = 800, kHeight = 600;
// Neighbouring pixels of one smooth surface differ in depth by far less; an occluding edge more.
constexpr double kDepthJump = 0.05;

struct Case {
    std::string shape;
    raster::ShapeKind kind;
    raster::Scene scene;
    std::vector<int> levels;
    int diary_level;
};

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace

std::vector<ShadingRow> measure_shading(int repetitions) {
    std::vector<Case> cases;
    cases.push_back({"sphere",
                     raster::ShapeKind::sphere,
                     raster::DiaryScene("phong-sphere").still(kWidth, kHeight),
                     {0, 1, 2, 3, 4, 5, 6, 7},
                     4});
    cases.push_back({"torus",
                     raster::ShapeKind::torus,
                     raster::DiaryScene("torus").still(kWidth, kHeight),
                     {1, 2, 3, 4, 6, 8, 12, 16, 24},
                     4});
    std::vector<ShadingRow> rows;
    for (Case& c : cases) {
        c.scene.background = kNoSurface;
        const raster::SceneObject& object = c.scene.objects.front();
        const std::vector<ExactObject> exact{
            {c.kind, object.model, std::get<raster::IntensityMaterial>(object.material)}};
        const ExactImage reference = ray_cast(c.scene.camera, kWidth, kHeight, exact, c.scene.lights, kNoSurface);
        const raster::DetailChoice chosen = raster::choose_detail(
            c.kind, object.model, c.scene.camera, std::get<raster::IntensityMaterial>(object.material), c.scene.lights);
        const raster::IntensityLighting lighting(std::get<raster::IntensityMaterial>(object.material), c.scene.lights,
                                                 -c.scene.camera.direction());
        const double stretch = c.scene.camera.scale() * raster::model_stretch(object.model).most;
        std::vector<raster::Scene> variants;
        for (const int level : c.levels) {
            const auto mesh = std::make_shared<const raster::Mesh>(raster::tessellate(c.kind, level));
            const raster::Mesh posed_mesh = raster::posed(*mesh, object.model);
            const double deviation = raster::surface_deviation(c.kind, *mesh) * stretch;
            for (const raster::ShadingMethod method :
                 {raster::ShadingMethod::flat, raster::ShadingMethod::gouraud, raster::ShadingMethod::phong}) {
                raster::Scene variant = c.scene;
                variant.objects.front().mesh = mesh;
                variant.objects.front().shading = method;
                raster::Framebuffer image(kWidth, kHeight);
                raster::DepthBuffer depth;
                raster::render(image, variant, depth);
                ShadingRow row{
                    c.shape,
                    level,
                    mesh->facets.size(),
                    method == raster::ShadingMethod::flat      ? "flat"
                    : method == raster::ShadingMethod::gouraud ? "gouraud"
                                                               : "phong",
                    deviation,
                    0,
                    0.0,
                    0.0,
                    raster::shading_error_levels(c.kind, posed_mesh, object.model, c.scene.camera, method, lighting),
                    0.0,
                    0.0,
                    0.0};
                std::int64_t both = 0;
                double total = 0.0;
                const auto covered_at = [&](int x, int y) {
                    return x >= 0 && y >= 0 && x < kWidth && y < kHeight && image.pixel(x, y) != kNoSurface;
                };
                const auto truly_at = [&](int x, int y) {
                    return x >= 0 && y >= 0 && x < kWidth && y < kHeight &&
                           reference.covered[static_cast<std::size_t>(y * kWidth + x)] != 0;
                };
                const auto depth_at = [&](int x, int y) {
                    return reference.depth[static_cast<std::size_t>(y * kWidth + x)];
                };
                for (int y = 0; y < kHeight; ++y) {
                    for (int x = 0; x < kWidth; ++x) {
                        const raster::Rgb mine = image.pixel(x, y);
                        if (covered_at(x, y) != truly_at(x, y)) ++row.outline_mismatches;
                        // Shading is judged inside the outlines: both images cover the 3 x 3 block and the
                        // true surface has no occluding edge in it (a jump in depth).
                        bool interior = true;
                        for (int dy = -1; dy <= 1; ++dy) {
                            for (int dx = -1; dx <= 1; ++dx) {
                                interior = interior && covered_at(x + dx, y + dy) && truly_at(x + dx, y + dy) &&
                                           std::abs(depth_at(x + dx, y + dy) - depth_at(x, y)) < kDepthJump;
                            }
                        }
                        if (!interior) continue;
                        const raster::Rgb exact_colour = reference.colour.pixel(x, y);
                        const double error =
                            std::max({std::abs(mine.r - exact_colour.r), std::abs(mine.g - exact_colour.g),
                                      std::abs(mine.b - exact_colour.b)});
                        total += error;
                        row.max_error = std::max(row.max_error, error);
                        ++both;
                    }
                }
                row.mean_error = both > 0 ? total / static_cast<double>(both) : 0.0;
                row.diary = level == c.diary_level && method == raster::ShadingMethod::phong;
                row.automatic = level == chosen.level && method == chosen.shading;
                rows.push_back(row);
                variants.push_back(variant);
            }
        }
        // Timings interleaved across every variant of the case, so drift hits them all alike.
        const std::size_t first = rows.size() - variants.size();
        std::vector<std::vector<double>> times(variants.size());
        raster::Framebuffer image(kWidth, kHeight);
        raster::DepthBuffer depth;
        for (int r = 0; r < repetitions; ++r) {
            for (std::size_t v = 0; v < variants.size(); ++v) {
                const auto start = std::chrono::steady_clock::now();
                raster::render(image, variants[v], depth);
                times[v].push_back(milliseconds_since(start));
            }
        }
        for (std::size_t v = 0; v < variants.size(); ++v) {
            rows[first + v].ms = median_of(times[v]);
            rows[first + v].ms_low = *std::min_element(times[v].begin(), times[v].end());
            rows[first + v].ms_high = *std::max_element(times[v].begin(), times[v].end());
        }
    }
    return rows;
}

}  // namespace lab
