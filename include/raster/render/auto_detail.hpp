#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/mesh.hpp>
#include <raster/geometry/shapes.hpp>
#include <raster/render/scene.hpp>
#include <raster/shade/intensity_lighting.hpp>
#include <raster/shade/linear_lighting.hpp>

#include <memory>
#include <optional>
#include <span>
#include <vector>
#include <glm/mat4x4.hpp>

// Tessellation and shading chosen from an object's size on screen (doc/lab/README.md#auto-detail):
// model no more than the pixels can show.
namespace raster {

// The diary's meshes by one number: the sphere's octahedron splits (0..kMaxSphereLevel), or the
// torus's factor f for torus(12 f, 8 f) (1..kMaxTorusLevel; the diary's torus(48, 32) is 4).
inline constexpr int kMaxTorusLevel = 64;
[[nodiscard]] Mesh tessellate(ShapeKind shape, int level);

// The farthest any point of the mesh lies from the true surface, in object units.
[[nodiscard]] double surface_deviation(ShapeKind shape, const Mesh& mesh);

// The targets: the outline within half a pixel of the true one, and every pixel's unrounded
// colour within one 8-bit level of the exact surface's.
inline constexpr double kSilhouetteTolerancePx = 0.5;
inline constexpr double kShadingToleranceLevels = 1.0;

struct DetailChoice {
    ShapeKind shape;
    int level;
    ShadingMethod shading;
    double silhouette_px;   // surface_deviation times the object's largest scale on screen
    double shading_levels;  // the largest estimated colour error, 8-bit levels before rounding
};

// The coarsest mesh whose outline meets the tolerance at this pose, then the first of flat,
// Gouraud and Phong (cheapest per pixel first) whose shading meets it, refining the mesh until
// one does. Shading error is estimated on the posed mesh against the shape's true normals.
[[nodiscard]] DetailChoice choose_detail(ShapeKind shape, const glm::mat4& model, const OrthoCamera& camera,
                                         const IntensityMaterial& material, std::span<const DirectionalLight> lights);
// The same for a linear material, its error measured after the sRGB encoding.
[[nodiscard]] DetailChoice choose_detail(ShapeKind shape, const glm::mat4& model, const OrthoCamera& camera,
                                         const LinearMaterial& material, std::span<const DirectionalLight> lights,
                                         std::span<const PointLight> points);

// One choice per object of a scene, made to hold over every sampled frame (the finest level and
// dearest shading any of them needs), with the meshes built once.
struct DetailPlan {
    std::vector<std::optional<DetailChoice>> choices;  // nothing for objects without a shape
    std::vector<std::shared_ptr<const Mesh>> meshes;   // the chosen mesh per object, or null
};
// Plans from sample frames of one clip (objects matched by index; all frames list the same ones).
[[nodiscard]] DetailPlan plan_detail(std::span<const Scene> samples);
// The frame with the planned meshes and shading in place of the scene's own.
[[nodiscard]] Scene with_detail(Scene frame, const DetailPlan& plan);

// The estimated shading error of one posed mesh and method, in 8-bit levels before rounding:
// at seven points of every facet that faces the camera, the shaded value against the exact one
// where the view line through that point first meets the true surface. Points within 1.5 px of
// an outline, or whose line first meets another sheet of the surface, are left to the outline.
[[nodiscard]] double shading_error_levels(ShapeKind shape, const Mesh& posed_mesh, const glm::mat4& model,
                                          const OrthoCamera& camera, ShadingMethod method,
                                          const IntensityLighting& lighting);
[[nodiscard]] double shading_error_levels(ShapeKind shape, const Mesh& posed_mesh, const glm::mat4& model,
                                          const OrthoCamera& camera, ShadingMethod method,
                                          const LinearLighting& lighting);

}  // namespace raster
