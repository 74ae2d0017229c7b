// perspective-lab's clipping and depth measures (lab/perspective_lab.cpp runs them).
#include "perspective_clip_depth.hpp"
#include "lab_args.hpp"
#include "perspective_floor.hpp"

#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/shade/shaders.hpp>
#include "rasterize/setup_perspective.hpp"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace perspective_lab {
namespace {

float as_float(double v) { return static_cast<float>(v); }

}  // namespace

const std::vector<DepthEncoding>& encodings() {
    static const std::vector<DepthEncoding> all{
        {"w as float (product)", [](double w, double, double) { return double{as_float(w)}; }},
        {"z/w as float", [](double w, double n, double f) { return double{as_float(f * (w - n) / ((f - n) * w))}; }},
        {"reversed z/w as float",
         [](double w, double n, double f) { return -double{as_float(n * (f - w) / ((f - n) * w))}; }},
        {"z/w in 24-bit fixed",
         [](double w, double n, double f) { return std::floor(f * (w - n) / ((f - n) * w) * 16777215.0 + 0.5); }},
        {"1/w as float", [](double w, double, double) { return -double{as_float(1.0 / w)}; }},
    };
    return all;
}

ClippingRow measure_clipping(std::string_view name, int fov) {
    const raster::Scene flat = raster::DiaryScene(name).still(kWidth, kHeight);
    const raster::PerspectiveScene scene = raster::in_perspective(flat, kWidth, kHeight, fov);
    const auto draw = [&](raster::Framebuffer& image, double band) {
        image.clear(scene.background);
        raster::DepthBuffer depth;
        depth.prepare(kWidth, kHeight);
        for (const raster::SceneObject& object : scene.objects) {
            const raster::Mesh mesh = raster::posed(*object.mesh, object.model);
            const raster::LinearLighting lighting(std::get<raster::LinearMaterial>(object.material), scene.lights,
                                                  scene.point_lights, -scene.camera.direction(), scene.camera.eye());
            raster::detail::draw_facets_in_perspective(image, &depth, scene.camera, mesh,
                                                       raster::LinearPhongShader{&lighting}, band);
        }
    };
    raster::Framebuffer six(kWidth, kHeight), guard(kWidth, kHeight);
    std::vector<double> six_ms, guard_ms;
    for (int r = 0; r < 31; ++r) {  // interleaved
        auto start = std::chrono::steady_clock::now();
        draw(six, 0.0);
        six_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        start = std::chrono::steady_clock::now();
        draw(guard, raster::detail::kGuardBandPixels);
        guard_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    long differing = 0;
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) differing += six.pixel(i, j) != guard.pixel(i, j) ? 1 : 0;
    }
    return {std::string(name), fov, differing, lab::median(six_ms), lab::median(guard_ms)};
}

std::vector<DepthRow> measure_depth() {
    std::vector<DepthRow> rows;
    const double gap = 1e-5, far = 1000.0;
    const raster::PerspectiveCamera camera = grazing_camera(10.0);
    for (const double ratio : {1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7}) {
        const double near = far / ratio;
        for (const DepthEncoding& encoding : encodings()) {
            DepthRow row{encoding.name, ratio, 0, 0};
            for (int j = 0; j < kHeight; ++j) {
                for (int i = 0; i < kWidth; ++i) {
                    const std::optional<glm::dvec2> hit = floor_at(camera, i, j);
                    if (!hit) continue;
                    // View depth along the camera's forward axis, for the floor at y = -1 and the
                    // one `gap` below it: the same ray, scaled by the heights.
                    const glm::dvec3 point(hit->x, -1.0, hit->y);
                    const double w_near = glm::dot(point, glm::dvec3(camera.direction()));
                    const double w_far = w_near * (1.0 + gap);
                    if (w_near < near || w_far > far) continue;
                    ++row.compared;
                    if (!(encoding.code(w_far, near, far) > encoding.code(w_near, near, far))) ++row.wrong;
                }
            }
            rows.push_back(row);
        }
    }
    return rows;
}

}  // namespace perspective_lab
