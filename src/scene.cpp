#include <raster/scene.hpp>

#include <raster/draw_mesh.hpp>
#include <raster/textured_shaders.hpp>

#include "clipped_facets.hpp"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>
#include <cmath>
#include <numbers>
#include <optional>
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

namespace {

// Lights one object by its material and hands `draw` the shader its shading method asks for.
// `eye` is the viewer's position in perspective; orthographic views have `to_eye` alone.
template <typename Draw>
std::size_t draw_shaded(const SceneObject& object, std::span<const DirectionalLight> lights,
                        std::span<const PointLight> points, glm::vec3 to_eye, std::optional<glm::vec3> eye,
                        std::optional<DepthDarkening> darkening, Draw draw) {
    if (const auto* phase1 = std::get_if<Material>(&object.material)) {
        // Phase 1's model has one viewer direction, the camera's, even in perspective.
        const Lighting lighting(*phase1, lights, to_eye);
        switch (object.shading) {
        case ShadingMethod::flat: return draw(FlatShader{&lighting});
        case ShadingMethod::gouraud: return draw(GouraudShader{&lighting});
        case ShadingMethod::phong: return draw(PhongShader{&lighting});
        case ShadingMethod::unlit: return draw(UnlitShader{{linear_from_srgb(phase1->base)}});
        }
        return 0;
    }
    const PhongMaterial& material = std::get<PhongMaterial>(object.material);
    const LinearLighting lighting(material, lights, points, to_eye, eye, darkening);
    const DiffuseSource diffuse{material.diffuse, object.texture.get(), object.sampler};
    if (object.shading == ShadingMethod::unlit) return draw(UnlitShader{diffuse});
    if (object.texture) {  // the textured shaders read the texture at every pixel
        switch (object.shading) {
        case ShadingMethod::flat: return draw(TexturedFlatShader{&lighting, diffuse});
        case ShadingMethod::gouraud: return draw(TexturedGouraudShader{&lighting, diffuse});
        default: return draw(TexturedPhongShader{&lighting, diffuse});
        }
    }
    switch (object.shading) {
    case ShadingMethod::flat: return draw(LinearFlatShader{&lighting});
    case ShadingMethod::gouraud: return draw(LinearGouraudShader{&lighting});
    default: return draw(LinearPhongShader{&lighting});
    }
}

// The threads a render uses: the count asked for (0: one per core), at most one per row.
int thread_count(int asked, int height) {
    if (asked < 0) throw std::invalid_argument("thread count must be 0 (one per core) or more, got " + std::to_string(asked));
    const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
    return std::clamp(asked == 0 ? cores : asked, 1, height);
}

// Clears to the background, prepares depth only when the scene needs it, and draws every posed
// object through `draw_mesh_with(depth or nullptr, rows, mesh, shader)`: on one thread, or on
// several, each clearing and drawing its own band of rows in the same object and facet order.
template <typename Camera, typename DrawMesh>
std::size_t render_objects(Framebuffer& framebuffer, const BasicScene<Camera>& scene, DepthBuffer& depth,
                           std::optional<glm::vec3> eye, RenderOptions options, DrawMesh draw_mesh_with) {
    const int threads = thread_count(options.threads, framebuffer.height());
    const bool depth_test = needs_depth(scene);
    if (depth_test) depth.resize(framebuffer.width(), framebuffer.height());  // each band clears its own rows
    DepthBuffer* const tested = depth_test ? &depth : nullptr;
    const glm::vec3 to_eye = -scene.camera.direction();
    std::vector<Mesh> meshes;  // posed once, drawn by every band
    for (const SceneObject& object : scene.objects) meshes.push_back(object.mesh ? posed(*object.mesh, object.model) : Mesh{});
    const auto draw_band = [&](std::optional<PixelRect> rows) {
        const int top = rows ? rows->y : 0, bottom = rows ? rows->y + rows->height : framebuffer.height();
        framebuffer.clear_rows(top, bottom, scene.background);
        if (tested != nullptr) tested->clear_rows(top, bottom);
        std::size_t drawn = 0;
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            if (!scene.objects[i].mesh) continue;  // an object without a mesh shows nothing
            drawn += draw_shaded(scene.objects[i], scene.lights, scene.point_lights, to_eye, eye, scene.darkening,
                                 [&](const auto& shader) { return draw_mesh_with(tested, rows, meshes[i], shader); });
        }
        return drawn;
    };
    if (threads == 1) return draw_band(std::nullopt);
    // Bands of whole rows, as even as the height allows; every band counts the same facets.
    std::vector<std::size_t> drawn(static_cast<std::size_t>(threads));
    std::vector<std::exception_ptr> failures(static_cast<std::size_t>(threads));
    {
        std::vector<std::jthread> workers;
        for (int t = 0; t < threads; ++t) {
            const int top = framebuffer.height() * t / threads, bottom = framebuffer.height() * (t + 1) / threads;
            workers.emplace_back([&, t, top, bottom] {
                try {
                    drawn[static_cast<std::size_t>(t)] = draw_band(PixelRect{0, top, framebuffer.width(), bottom - top});
                } catch (...) {
                    failures[static_cast<std::size_t>(t)] = std::current_exception();
                }
            });
        }
    }
    for (const std::exception_ptr& failure : failures) {
        if (failure) std::rethrow_exception(failure);
    }
    return drawn.front();
}

}  // namespace

std::size_t render(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth, RenderOptions options) {
    // Orthographic: the direction toward the viewer is the same at every pixel.
    return render_objects(framebuffer, scene, depth, std::nullopt, options,
                          [&](DepthBuffer* tested, std::optional<PixelRect> rows, const Mesh& mesh, const auto& shader) {
                              return draw_mesh({framebuffer, tested, rows}, scene.camera, mesh, shader);
                          });
}

std::size_t render(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth, RenderOptions options) {
    // Phase 2 takes the direction toward the eye at every point.
    return render_objects(framebuffer, scene, depth, scene.camera.eye(), options,
                          [&](DepthBuffer* tested, std::optional<PixelRect> rows, const Mesh& mesh, const auto& shader) {
                              return detail::draw_facets_in_perspective(framebuffer, tested, scene.camera, mesh, shader,
                                                                        detail::kGuardBandPixels, rows);
                          });
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
    return {camera, scene.background, scene.lights, scene.point_lights, scene.objects, scene.darkening};
}

}  // namespace raster
