#include <raster/render/scene.hpp>

#include <raster/camera/perspective_camera.hpp>

namespace raster {

bool needs_depth(std::span<const SceneObject> objects) noexcept {
    std::size_t meshes = 0;
    bool convex = true;
    for (const SceneObject& object : objects) {
        if (!object.mesh) continue;
        ++meshes;
        convex = convex && object.mesh->convex;
    }
    return meshes > 1 || !convex;
}

PerspectiveScene in_perspective(const Scene& scene, int width, int height, double fov_degrees) {
    const PerspectiveCamera camera = perspective_matching(scene.camera, width, height, fov_degrees);
    return {camera, scene.background, scene.lights, scene.point_lights, scene.objects, scene.darkening};
}

}  // namespace raster
