#include <raster/scene.hpp>

#include <raster/draw_mesh.hpp>

#include "clipped_facets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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
    const OrthoCamera& flat = scene.camera;
    const glm::dvec3 eye(flat.eye()), ahead(flat.direction());
    const double to_origin = glm::dot(-eye, ahead);
    // Pixels per world unit match the orthographic camera's on the plane through the origin.
    const double half_angle = fov_degrees * std::numbers::pi / 360.0;
    const double distance = height / (2.0 * std::max(flat.scale(), 0.5) * std::tan(half_angle));
    const glm::dvec3 moved = eye + (to_origin - distance) * ahead;
    const PerspectiveCamera::Lens lens{fov_degrees, distance / 100.0, distance + 100.0};
    // A target as far off as the eye itself, so that both stay apart as floats.
    const glm::dvec3 target = moved + ahead * std::max(1.0, glm::length(moved));
    const PerspectiveCamera camera = PerspectiveCamera::look_at(width, height, glm::vec3(moved), glm::vec3(target), flat.up(), lens);
    return {camera, scene.background, scene.lights, scene.point_lights, scene.objects};
}

}  // namespace raster
