#include <raster/scene.hpp>

#include <raster/draw_mesh.hpp>

#include "clipped_facets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

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

std::size_t render(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth) {
    framebuffer.clear(scene.background);
    const bool depth_test = needs_depth(scene);
    if (depth_test) depth.prepare(framebuffer.width(), framebuffer.height());
    const RenderTarget target{framebuffer, depth_test ? &depth : nullptr};
    // Orthographic: the direction toward the viewer is the same at every pixel.
    const glm::vec3 to_eye = -scene.camera.direction();
    std::size_t drawn = 0;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;  // an object without a mesh shows nothing
        const Mesh mesh = posed(*object.mesh, object.model);
        if (const auto* phase1 = std::get_if<Material>(&object.material)) {
            const Lighting lighting(*phase1, scene.lights, to_eye);
            switch (object.shading) {
            case ShadingMethod::flat: drawn += draw_mesh(target, scene.camera, mesh, FlatShader{&lighting}); break;
            case ShadingMethod::gouraud: drawn += draw_mesh(target, scene.camera, mesh, GouraudShader{&lighting}); break;
            case ShadingMethod::phong: drawn += draw_mesh(target, scene.camera, mesh, PhongShader{&lighting}); break;
            }
            continue;
        }
        const LinearLighting lighting(std::get<PhongMaterial>(object.material), scene.lights, scene.point_lights, to_eye);
        switch (object.shading) {
        case ShadingMethod::flat: drawn += draw_mesh(target, scene.camera, mesh, LinearFlatShader{&lighting}); break;
        case ShadingMethod::gouraud: drawn += draw_mesh(target, scene.camera, mesh, LinearGouraudShader{&lighting}); break;
        case ShadingMethod::phong: drawn += draw_mesh(target, scene.camera, mesh, LinearPhongShader{&lighting}); break;
        }
    }
    return drawn;
}

std::size_t render(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth) {
    framebuffer.clear(scene.background);
    const bool depth_test = needs_depth(scene);
    if (depth_test) depth.prepare(framebuffer.width(), framebuffer.height());
    DepthBuffer* const target = depth_test ? &depth : nullptr;
    const PerspectiveCamera& camera = scene.camera;
    // Phase 1's model has one viewer direction: the camera's; Phase 2 takes it at every point.
    const glm::vec3 ahead = -camera.direction();
    std::size_t drawn = 0;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        const Mesh mesh = posed(*object.mesh, object.model);
        const auto draw = [&](const auto& shader) {
            drawn += detail::draw_facets_in_perspective(framebuffer, target, camera, mesh, shader);
        };
        if (const auto* phase1 = std::get_if<Material>(&object.material)) {
            const Lighting lighting(*phase1, scene.lights, ahead);
            switch (object.shading) {
            case ShadingMethod::flat: draw(FlatShader{&lighting}); break;
            case ShadingMethod::gouraud: draw(GouraudShader{&lighting}); break;
            case ShadingMethod::phong: draw(PhongShader{&lighting}); break;
            }
            continue;
        }
        const LinearLighting lighting(std::get<PhongMaterial>(object.material), scene.lights, scene.point_lights, ahead,
                                      camera.eye());
        switch (object.shading) {
        case ShadingMethod::flat: draw(LinearFlatShader{&lighting}); break;
        case ShadingMethod::gouraud: draw(LinearGouraudShader{&lighting}); break;
        case ShadingMethod::phong: draw(LinearPhongShader{&lighting}); break;
        }
    }
    return drawn;
}

PerspectiveScene in_perspective(const Scene& scene, int width, int height, double fov_degrees) {
    if (!(fov_degrees > 0.0 && fov_degrees < 180.0)) {
        throw std::invalid_argument("field of view must be between 0 and 180 degrees, got " + std::to_string(fov_degrees));
    }
    const OrthoCamera& flat = scene.camera;
    const double to_origin = flat.view_from_world(glm::vec3(0.0F)).z;
    // Pixels per world unit match the orthographic camera's on the plane through the origin.
    const double half_angle = fov_degrees * std::numbers::pi / 360.0;
    const double distance = height / (2.0 * std::max(flat.scale(), 0.5) * std::tan(half_angle));
    const PerspectiveCamera::Lens lens{fov_degrees, distance / 100.0, distance + 100.0};
    // The same axes, the eye moved in double precision: no rounding through floats on the way.
    const OrthoCamera moved = flat.dollied(to_origin - distance);
    if (!std::isfinite(glm::length(glm::dvec3(moved.eye())))) throw std::invalid_argument("camera eye is too far out to move back");
    const PerspectiveCamera camera = PerspectiveCamera::from_view(moved, width, height, lens);
    return {camera, scene.background, scene.lights, scene.point_lights, scene.objects};
}

}  // namespace raster
