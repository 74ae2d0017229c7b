#include <raster/geometry/mesh.hpp>
#include <raster/shade/gltf_brdf.hpp>
#include <raster/shade/metallic_roughness_lighting.hpp>
#include <raster/shade/normal_map.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/matrix.hpp>

namespace raster {
namespace {

bool usable(const PointLight& light) noexcept {
    const glm::vec3& p = light.position;
    const Falloff& f = light.falloff;
    const bool finite = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
                        std::isfinite(light.intensity) && std::isfinite(f.constant) && std::isfinite(f.linear) &&
                        std::isfinite(f.quadratic);
    return finite && f.constant >= 0.0F && f.linear >= 0.0F && f.quadratic >= 0.0F &&
           (f.constant > 0.0F || f.linear > 0.0F || f.quadratic > 0.0F);
}

// The vertex frame (t, w) turned to the coordinates a texture transform A moves the map's to:
// [t' b'] = [t b] A^-1 (doc/conventions.md#normal-maps); zero, for the cotangent frame, where A is singular.
glm::vec4 moved_tangent(glm::vec4 tangent, glm::vec3 n, const TextureTransform& moved) noexcept {
    if (moved.identity()) return tangent;
    const UvFootprint columns = moved_uv(moved, {0.0F, 0.0F}, {{1.0F, 0.0F}, {0.0F, 1.0F}}).footprint;
    const glm::mat2 a(columns.per_pixel_x, columns.per_pixel_y);
    const float det = glm::determinant(a);
    if (!(std::abs(det) > 1e-12F) || !std::isfinite(det)) return glm::vec4(0.0F);
    const glm::mat2 inverse = glm::inverse(a);
    const glm::vec3 t(tangent);
    const glm::vec3 b = glm::cross(n, t) * (tangent.w < 0.0F ? -1.0F : 1.0F);
    const glm::vec3 along_u = t * inverse[0][0] + b * inverse[0][1];
    const glm::vec3 along_v = t * inverse[1][0] + b * inverse[1][1];
    return {along_u, glm::dot(glm::cross(n, along_u), along_v) < 0.0F ? -1.0F : 1.0F};
}

}  // namespace

MetallicRoughnessLighting::MetallicRoughnessLighting(const MetallicRoughness& material, Sampler sampler,
                                                     const Surroundings* surroundings,
                                                     std::span<const DirectionalLight> directional,
                                                     std::span<const PointLight> points, glm::vec3 to_eye,
                                                     std::optional<glm::vec3> eye)
    : material_(material.usable()), sampler_(sampler), surroundings_(surroundings), to_eye_(unit_or_zero(to_eye)),
      eye_(eye) {
    for (const DirectionalLight& light : directional) {
        PreparedLight ready = prepare_light(light, to_eye_);
        ready.intensity = std::clamp(ready.intensity, -LinearLighting::kBrightest, LinearLighting::kBrightest);
        if (ready.intensity != 0.0F) directional_.push_back(ready);
    }
    for (const PointLight& light : points) {
        if (usable(light) && light.intensity != 0.0F)
            points_.push_back({light.position, light.intensity, light.falloff});
    }
}

MaterialSample MetallicRoughnessLighting::sample(const MaterialPoint& point) const noexcept {
    const MetallicRoughness& m = material_;
    // Each map read where its KHR_texture_transform moves the point.
    const auto read = [&](const std::shared_ptr<const Texture>& map, const TextureTransform& transform) {
        const MovedUv at = moved_uv(transform, point.uv, point.footprint);
        return map->sample(at.uv, at.footprint, sampler_);
    };
    MaterialSample out{m.base_colour * point.tint, m.metallic, m.roughness, 1.0F, m.emissive,
                       unit_or_zero(point.normal)};
    if (m.base_colour_map) out.base_colour = out.base_colour * read(m.base_colour_map, m.base_colour_transform);
    if (m.metallic_roughness_map) {
        const LinearRgb texel = read(m.metallic_roughness_map, m.metallic_roughness_transform);
        out.metallic *= texel.b, out.roughness *= texel.g;
    }
    if (m.occlusion_map)
        out.occlusion = 1.0F + m.occlusion_strength * (read(m.occlusion_map, m.occlusion_transform).r - 1.0F);
    if (m.emissive_map) out.emissive = out.emissive * read(m.emissive_map, m.emissive_transform);
    if (m.normal_map && glm::dot(out.normal, out.normal) > 0.0F) {
        const TextureTransform& moved = m.normal_transform;
        const UvFootprint footprint = moved_uv(moved, point.uv, point.footprint).footprint;
        out.normal = normal_mapped(out.normal, read(m.normal_map, moved), m.normal_scale,
                                   moved_tangent(point.tangent, out.normal, moved), point.position_per_x,
                                   point.position_per_y, footprint);
    }
    return out;
}

LinearRgb MetallicRoughnessLighting::shade(glm::vec3 position, const MaterialSample& s) const noexcept {
    if (!(glm::dot(s.normal, s.normal) > 0.0F)) return s.emissive;
    glm::vec3 to_eye = to_eye_;
    if (eye_) {
        const glm::vec3 toward = unit_or_zero(*eye_ - position);
        if (glm::dot(toward, toward) > 0.0F) to_eye = toward;
    }
    // A normal interpolated past the silhouette is bent back just far enough to see the viewer.
    glm::vec3 n = s.normal;
    constexpr float kGrazing = 1e-3F;
    const float facing = glm::dot(n, to_eye);
    if (facing < kGrazing) n = unit_or_zero(n + to_eye * (kGrazing - facing));
    if (!(glm::dot(n, n) > 0.0F)) return s.emissive;
    LinearRgb direct{};
    const auto light = [&](glm::vec3 toward, float arriving) {
        const float n_dot_l = glm::dot(n, toward);
        if (n_dot_l > 0.0F)
            direct = direct + gltf_brdf::brdf(s.base_colour, s.metallic, s.roughness, n, to_eye, toward) *
                                  (gltf_brdf::kPi * arriving * n_dot_l);
    };
    for (const PreparedLight& l : directional_) light(l.toward, l.intensity);
    for (const PreparedPointLight& p : points_) {
        const glm::vec3 offset = p.position - position;
        const float distance = glm::length(offset);
        if (distance > 0.0F && std::isfinite(distance))
            light(offset / distance, LinearLighting::attenuated(p, distance));
    }
    LinearRgb surrounding{};
    if (surroundings_ != nullptr) {
        const float n_dot_v = std::clamp(glm::dot(n, to_eye), 0.0F, 1.0F);
        const LinearRgb f0 = gltf_brdf::f0_of(s.base_colour, s.metallic);
        const SplitSumTable::Specular split = surroundings_->table().specular(n_dot_v, s.roughness);
        const glm::vec3 reflected = 2.0F * glm::dot(n, to_eye) * n - to_eye;
        const LinearRgb specular = surroundings_->specular(reflected, s.roughness) *
                                   (f0 * split.scale + LinearRgb{split.bias, split.bias, split.bias});
        const LinearRgb c_diff = s.base_colour * (1.0F - s.metallic);
        const LinearRgb diffuse = surroundings_->diffuse(n) * c_diff * (LinearRgb{1.0F, 1.0F, 1.0F} - f0) *
                                  surroundings_->table().diffuse(n_dot_v);
        surrounding = (specular + diffuse) * s.occlusion;
    }
    const LinearRgb total = s.emissive + direct + surrounding;
    const auto finite = [](float c) { return std::isfinite(c) ? c : 0.0F; };
    return {finite(total.r), finite(total.g), finite(total.b)};
}

}  // namespace raster
