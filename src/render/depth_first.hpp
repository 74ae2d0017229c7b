#pragma once

#include <raster/render/scene.hpp>

// Whether a scene is drawn depth first when RenderOptions leaves it to us: every object's depth
// in a pass of its own, then the shading pass colours only what is nearest. The picture is the
// same either way; only the time differs, and the bench decided the rule
// (doc/performance.md#depth-first).
namespace raster::detail {

// The share of the screen the bounding boxes of a scene's objects cover, summed over the objects:
// 1 when they tile the screen once, more where they overlap. An object with a corner at or
// behind the eye counts as the whole screen.
[[nodiscard]] double screen_cover(const Scene& scene, int width, int height);
[[nodiscard]] double screen_cover(const PerspectiveScene& scene, int width, int height);

// Depth first pays when a pixel would be shaded several times at a per-pixel cost: a depth test,
// an object lit or textured per pixel, and objects whose boxes cover the screen 1.5 times or more.
inline constexpr double kDepthFirstCover = 1.5;

template <typename Camera>
[[nodiscard]] bool depth_first(const BasicScene<Camera>& scene, bool depth_test, int width, int height) {
    if (!depth_test || scene.objects.size() < 2) return false;
    bool per_pixel = false;
    for (const SceneObject& object : scene.objects) {
        per_pixel =
            per_pixel ||
            (object.mesh && (object.shading == ShadingMethod::phong || object.texture || object.phong_maps.any()));
    }
    return per_pixel && screen_cover(scene, width, height) >= kDepthFirstCover;
}

}  // namespace raster::detail
