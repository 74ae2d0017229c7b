#include <raster/render/scene.hpp>

#include <raster/camera/perspective_camera.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raster {

bool needs_depth(std::span<const SceneObject> objects) noexcept {
    std::size_t meshes = 0;
    bool convex = true;
    for (const SceneObject& object : objects) {
        if (!object.mesh) continue;
        ++meshes;
        // Splats and lines overlap one another and the surfaces they lie on.
        convex = convex && object.mesh->convex && object.mesh->points.empty() && object.mesh->segments.empty();
    }
    return meshes > 1 || !convex;
}

PerspectiveScene in_perspective(const Scene& scene, int width, int height, double fov_degrees) {
    const PerspectiveCamera camera = perspective_matching(scene.camera, width, height, fov_degrees);
    PerspectiveScene seen{camera, scene.background, scene.lights, scene.point_lights, scene.objects, scene.darkening};
    seen.points_and_lines = scene.points_and_lines;
    return seen;
}

double automatic_point_size(double area, std::size_t count) noexcept {
    if (count == 0 || !(area > 0.0)) return kMinPointSize;
    return std::clamp(2.5 * std::sqrt(area / static_cast<double>(count)), kMinPointSize, 16.0);
}

void check_points_and_lines(const PointsAndLines& style) {
    const auto within = [](double v, double low, double high) { return std::isfinite(v) && v >= low && v <= high; };
    if (style.point_size && !within(*style.point_size, kMinPointSize, kMaxPointSize)) {
        throw std::invalid_argument("point size must be from 1 to 64 pixels, got " + std::to_string(*style.point_size));
    }
    if (!within(style.line_width, kMinLineWidth, kMaxLineWidth)) {
        throw std::invalid_argument("line width must be from 0.5 to 64 pixels, got " +
                                    std::to_string(style.line_width));
    }
}

}  // namespace raster
