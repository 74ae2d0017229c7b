#include "render/depth_first.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace raster::detail {
namespace {

// The eight corners of a mesh's bounding box, moved by `model`; none for an empty mesh.
std::vector<glm::vec3> box_corners(const Mesh& mesh, const glm::mat4& model) {
    if (mesh.positions.empty()) return {};
    glm::vec3 low = mesh.positions.front(), high = low;
    for (const glm::vec3& p : mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
    std::vector<glm::vec3> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 c((i & 1) != 0 ? high.x : low.x, (i & 2) != 0 ? high.y : low.y, (i & 4) != 0 ? high.z : low.z);
        corners.emplace_back(model * glm::vec4(c, 1.0F));
    }
    return corners;
}

// The share of a width x height screen inside the box of `points` (screen coordinates).
double share_of_screen(const std::vector<glm::dvec2>& points, int width, int height) {
    if (points.empty()) return 0.0;
    glm::dvec2 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const glm::dvec2& p : points) low = glm::min(low, p), high = glm::max(high, p);
    const double w =
        std::clamp(high.x, 0.0, static_cast<double>(width)) - std::clamp(low.x, 0.0, static_cast<double>(width));
    const double h =
        std::clamp(high.y, 0.0, static_cast<double>(height)) - std::clamp(low.y, 0.0, static_cast<double>(height));
    const double share = std::max(0.0, w) * std::max(0.0, h) / (static_cast<double>(width) * height);
    return share == share ? share : 1.0;  // NaN from a non-finite mesh: the whole screen
}

}  // namespace

double screen_cover(const Scene& scene, int width, int height) {
    double cover = 0.0;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        std::vector<glm::dvec2> points;
        for (const glm::vec3& corner : box_corners(*object.mesh, object.model))
            points.push_back(scene.camera.screen_from_world(corner));
        cover += share_of_screen(points, width, height);
    }
    return cover;
}

double screen_cover(const PerspectiveScene& scene, int width, int height) {
    double cover = 0.0;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        std::vector<glm::dvec2> points;
        bool behind = false;
        for (const glm::vec3& corner : box_corners(*object.mesh, object.model)) {
            const glm::dvec4 clip = scene.camera.clip_from_world(corner);
            behind = behind || !(clip.w > scene.camera.lens().near);
            points.push_back(scene.camera.screen_from_clip(clip));
        }
        cover += behind ? 1.0 : share_of_screen(points, width, height);
    }
    return cover;
}

}  // namespace raster::detail
