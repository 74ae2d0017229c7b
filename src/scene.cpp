#include <raster/scene.hpp>

#include <raster/draw_mesh.hpp>

namespace raster {

bool needs_depth(const Scene& scene) noexcept {
    std::size_t meshes = 0;
    bool convex = true;
    for (const SceneObject& object : scene.objects) {
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

}  // namespace raster
