// Each shape's mesh, its error and the detail plan built on it; stays whole so the estimate reads in one pass.
#include <raster/render/auto_detail.hpp>

#include <raster/geometry/analytic_shape.hpp>
#include <raster/image/colour.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster {
namespace {

// Barycentric points where facets are checked: corners, edge midpoints, centroid.
constexpr std::array<glm::dvec3, 7> kSamples{
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}, {1.0 / 3, 1.0 / 3, 1.0 / 3}}};

// The torus levels tried, about sqrt(2) apart; every sphere level is tried.
constexpr std::array<int, 12> kTorusLevels{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64};

// The tightest radius of curvature, which sets how fast the view turns grazing near an outline.
double tightest_radius(ShapeKind shape) { return shape == ShapeKind::sphere ? 1.0 : kTorusTubeRadius; }

std::vector<int> levels_of(ShapeKind shape) {
    if (shape == ShapeKind::torus) return {kTorusLevels.begin(), kTorusLevels.end()};
    std::vector<int> levels;
    for (int level = 0; level <= kMaxSphereLevel; ++level) levels.push_back(level);
    return levels;
}

}  // namespace

Mesh tessellate(ShapeKind shape, int level) {
    if (shape == ShapeKind::sphere) return sphere(level);
    if (level < 1 || level > kMaxTorusLevel) {
        throw std::invalid_argument("torus level must be 1.." + std::to_string(kMaxTorusLevel) + ", got " +
                                    std::to_string(level));
    }
    return torus(12 * level, 8 * level);
}

double surface_deviation(ShapeKind shape, const Mesh& mesh) {
    double worst = 0.0;
    for (const Facet& facet : mesh.facets) {
        for (const glm::dvec3& b : kSamples) {
            const glm::dvec3 p = b.x * glm::dvec3(mesh.positions[facet.corners[0]]) +
                                 b.y * glm::dvec3(mesh.positions[facet.corners[1]]) +
                                 b.z * glm::dvec3(mesh.positions[facet.corners[2]]);
            worst = std::max(worst, std::abs(distance_to_surface(shape, p)));
        }
    }
    return worst;
}

namespace {

// What the estimate needs of a surface's light in 8-bit intensity: the intensity a Gouraud shader
// interpolates, and how far apart two intensities are in 8-bit levels of the brightest channel.
struct IntensityModel {
    const IntensityLighting& lighting;
    double brightest;
    using Value = float;
    [[nodiscard]] Value value(glm::vec3 /*position*/, glm::vec3 normal) const { return lighting.intensity(normal); }
    [[nodiscard]] double levels_apart(Value a, Value b) const {
        return std::abs(static_cast<double>(a) - b) * brightest;
    }
    [[nodiscard]] static Value mix(const std::array<Value, 3>& v, const glm::dvec3& b) {
        return static_cast<float>(b.x * v[0] + b.y * v[1] + b.z * v[2]);
    }
};

// In linear light: the colour a Gouraud shader interpolates, compared after the clamp and the
// sRGB encoding (unrounded), the largest channel difference.
struct LinearModel {
    const LinearLighting& lighting;
    using Value = LinearRgb;
    [[nodiscard]] Value value(glm::vec3 position, glm::vec3 normal) const { return lighting.shade(position, normal); }
    [[nodiscard]] static double levels(float v) {
        return 255.0 * srgb_from_linear_channel(std::clamp(double{v}, 0.0, 1.0));
    }
    [[nodiscard]] double levels_apart(Value a, Value b) const {
        return std::max({std::abs(levels(a.r) - levels(b.r)), std::abs(levels(a.g) - levels(b.g)),
                         std::abs(levels(a.b) - levels(b.b))});
    }
    [[nodiscard]] static Value mix(const std::array<Value, 3>& v, const glm::dvec3& b) {
        return v[0] * static_cast<float>(b.x) + v[1] * static_cast<float>(b.y) + v[2] * static_cast<float>(b.z);
    }
};

template <typename Model>
double error_levels(ShapeKind shape, const Mesh& posed_mesh, const glm::mat4& model, const OrthoCamera& camera,
                    ShadingMethod method, const Model& light) {
    using Value = typename Model::Value;
    const glm::dmat4 world_from_object(model);
    const glm::dmat4 object_from_world = glm::inverse(world_from_object);
    const glm::dvec3 view(camera.direction());
    const glm::dvec3 object_view = glm::dvec3(object_from_world * glm::dvec4(view, 0.0));
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(glm::mat3(model))));
    // Points within 1.5 px of an outline are the silhouette's business: there the view meets a
    // surface of curvature radius R px at |n . v| < sqrt(2 * 1.5 / R). A non-uniform scale bends
    // a radius r into as little as r * least^2 / most.
    const Stretch stretch = model_stretch(model);
    const double radius_px =
        stretch.most > 0.0 ? tightest_radius(shape) * camera.scale() * stretch.least * stretch.least / stretch.most
                           : 0.0;
    const double grazing = std::sqrt(3.0 / std::max(radius_px, 3.0));
    const bool faceted = posed_mesh.surface == Surface::faceted;
    double worst = 0.0;
    for (const Facet& facet : posed_mesh.facets) {
        if (!(glm::dot(glm::dvec3(facet.normal), view) < 0.0)) continue;  // facing away: never seen
        std::array<glm::vec3, 3> positions{};
        std::array<glm::vec3, 3> normals{};
        std::array<Value, 3> corner_values{};
        for (std::size_t k = 0; k < 3; ++k) {
            positions[k] = posed_mesh.positions[facet.corners[k]];
            normals[k] = faceted ? facet.normal : posed_mesh.normals[facet.corners[k]];
            corner_values[k] = light.value(positions[k], normals[k]);
        }
        const Value flat = light.value(positions[0] / 3.0F + positions[1] / 3.0F + positions[2] / 3.0F, facet.normal);
        for (const glm::dvec3& b : kSamples) {
            const glm::dvec3 world =
                b.x * glm::dvec3(positions[0]) + b.y * glm::dvec3(positions[1]) + b.z * glm::dvec3(positions[2]);
            // The exact image shows, at this point's pixel, the first surface along the view line.
            const glm::dvec3 object(object_from_world * glm::dvec4(world, 1.0));
            const std::optional<double> t = first_hit(shape, object, object_view);
            if (!t) continue;  // the true outline passes inside this point
            const glm::dvec3 hit = object + *t * object_view;
            const glm::dvec3 truth = glm::normalize(normal_matrix * surface_normal(shape, hit));
            if (std::abs(glm::dot(truth, view)) < grazing) continue;
            // Farther along the view than the mesh's gap allows, the hit is another sheet of the
            // surface: an occluding edge, left to the outline too.
            const double gap = std::abs(distance_to_surface(shape, object));
            const double slant = std::abs(glm::dot(surface_normal(shape, object), glm::normalize(object_view)));
            if (std::abs(*t) * glm::length(object_view) > 2.0 * gap / std::max(slant, grazing) + 1e-9) continue;
            const Value exact = light.value(glm::vec3(world_from_object * glm::dvec4(hit, 1.0)), glm::vec3(truth));
            Value estimate = flat;
            if (method == ShadingMethod::gouraud) {
                estimate = Model::mix(corner_values, b);
            } else if (method == ShadingMethod::phong) {
                const glm::dvec3 n =
                    b.x * glm::dvec3(normals[0]) + b.y * glm::dvec3(normals[1]) + b.z * glm::dvec3(normals[2]);
                estimate = light.value(glm::vec3(world), unit_or_zero(glm::vec3(n)));
            }
            worst = std::max(worst, light.levels_apart(estimate, exact));
        }
    }
    return worst;
}

}  // namespace

double shading_error_levels(ShapeKind shape, const Mesh& posed_mesh, const glm::mat4& model, const OrthoCamera& camera,
                            ShadingMethod method, const IntensityLighting& lighting) {
    const Rgb base = lighting.material.base;
    const IntensityModel light{lighting, static_cast<double>(std::max({base.r, base.g, base.b}))};
    return error_levels(shape, posed_mesh, model, camera, method, light);
}

double shading_error_levels(ShapeKind shape, const Mesh& posed_mesh, const glm::mat4& model, const OrthoCamera& camera,
                            ShadingMethod method, const LinearLighting& lighting) {
    return error_levels(shape, posed_mesh, model, camera, method, LinearModel{lighting});
}

namespace {

// The coarsest level whose outline meets the tolerance, then the cheapest method whose shading does.
template <typename Light>
DetailChoice choose(ShapeKind shape, const glm::mat4& model, const OrthoCamera& camera, const Light& lighting) {
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            if (!std::isfinite(model[column][row]))
                throw std::invalid_argument("automatic detail needs a finite model matrix");
        }
    }
    const double stretch = camera.scale() * model_stretch(model).most;
    const std::vector<int> levels = levels_of(shape);
    DetailChoice choice{};
    for (const int level : levels) {
        const Mesh mesh = tessellate(shape, level);
        choice = {shape, level, ShadingMethod::phong, surface_deviation(shape, mesh) * stretch, 0.0};
        if (choice.silhouette_px >= kSilhouetteTolerancePx && level != levels.back()) continue;
        const Mesh posed_mesh = posed(mesh, model);
        for (const ShadingMethod method : {ShadingMethod::flat, ShadingMethod::gouraud, ShadingMethod::phong}) {
            choice.shading = method;
            choice.shading_levels = shading_error_levels(shape, posed_mesh, model, camera, method, lighting);
            if (choice.shading_levels < kShadingToleranceLevels) return choice;
        }
    }
    return choice;  // the finest mesh with Phong: the best on offer
}

}  // namespace

DetailChoice choose_detail(ShapeKind shape, const glm::mat4& model, const OrthoCamera& camera,
                           const IntensityMaterial& material, std::span<const DirectionalLight> lights) {
    return choose(shape, model, camera, IntensityLighting(material, lights, -camera.direction()));
}

DetailChoice choose_detail(ShapeKind shape, const glm::mat4& model, const OrthoCamera& camera,
                           const LinearMaterial& material, std::span<const DirectionalLight> lights,
                           std::span<const PointLight> points) {
    return choose(shape, model, camera, LinearLighting(material, lights, points, -camera.direction()));
}

DetailPlan plan_detail(std::span<const Scene> samples) {
    DetailPlan plan;
    if (samples.empty()) return plan;
    const std::size_t objects = samples.front().objects.size();
    plan.choices.resize(objects);
    plan.meshes.resize(objects);
    for (const Scene& frame : samples) {
        for (std::size_t i = 0; i < objects && i < frame.objects.size(); ++i) {
            const SceneObject& object = frame.objects[i];
            // Metallic-roughness is shaded per pixel: no cheaper method to choose.
            if (!object.shape || std::holds_alternative<MetallicRoughness>(object.material)) continue;
            const auto* intensity = std::get_if<IntensityMaterial>(&object.material);
            const DetailChoice choice =
                intensity != nullptr
                    ? choose_detail(*object.shape, object.model, frame.camera, *intensity, frame.lights)
                    : choose_detail(*object.shape, object.model, frame.camera,
                                    std::get<LinearMaterial>(object.material), frame.lights, frame.point_lights);
            std::optional<DetailChoice>& kept = plan.choices[i];
            if (!kept) {
                kept = choice;
                continue;
            }
            kept->shading = std::max(kept->shading, choice.shading);  // enumerators run cheapest first
            if (choice.level > kept->level) kept->level = choice.level;
            kept->silhouette_px = std::max(kept->silhouette_px, choice.silhouette_px);
            kept->shading_levels = std::max(kept->shading_levels, choice.shading_levels);
        }
    }
    for (std::size_t i = 0; i < objects; ++i) {
        if (plan.choices[i]) {
            plan.meshes[i] = std::make_shared<const Mesh>(tessellate(plan.choices[i]->shape, plan.choices[i]->level));
        }
    }
    return plan;
}

Scene with_detail(Scene frame, const DetailPlan& plan) {
    for (std::size_t i = 0; i < frame.objects.size() && i < plan.choices.size(); ++i) {
        if (!plan.choices[i]) continue;
        frame.objects[i].mesh = plan.meshes[i];
        frame.objects[i].shading = plan.choices[i]->shading;
    }
    return frame;
}

}  // namespace raster
