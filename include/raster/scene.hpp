#pragma once

#include <raster/depth_buffer.hpp>
#include <raster/framebuffer.hpp>
#include <raster/lighting.hpp>
#include <raster/linear_lighting.hpp>
#include <raster/mesh.hpp>
#include <raster/ortho_camera.hpp>
#include <raster/shapes.hpp>

#include <memory>
#include <optional>
#include <variant>
#include <vector>
#include <glm/mat4x4.hpp>

namespace raster {

// How an object's colour is computed: per facet, per vertex, or per pixel.
enum class ShadingMethod { flat, gouraud, phong };

// How a surface takes light: the diary's Phase 1 intensity on 8-bit colour, or Phase 2's
// material colours in linear light (doc/conventions.md#light).
using SurfaceMaterial = std::variant<Material, PhongMaterial>;

// A mesh placed in the world with its surface; one without a mesh draws nothing.
struct SceneObject {
    std::shared_ptr<const Mesh> mesh;
    glm::mat4 model{1.0F};
    SurfaceMaterial material;
    ShadingMethod shading = ShadingMethod::phong;
    // The true surface the mesh approximates, if any, so its detail can be chosen (auto_detail.hpp).
    std::optional<ShapeKind> shape{};
};

// Everything one frame shows.
struct Scene {
    OrthoCamera camera;
    Rgb background{0, 0, 0};
    std::vector<DirectionalLight> lights;
    // Point lights light Phase 2 materials only; the Phase 1 model knew directional light alone.
    std::vector<PointLight> point_lights;
    std::vector<SceneObject> objects;
};

// Whether the scene can hide one surface behind another once back faces are culled: more than
// one object, or a mesh that is not convex (doc/conventions.md#depth).
[[nodiscard]] bool needs_depth(const Scene& scene) noexcept;

// Clears to the background and draws every object; `depth` is prepared and used only when the
// scene needs it, so a lone convex mesh never touches it. Returns the facets drawn.
std::size_t render(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth);

}  // namespace raster
