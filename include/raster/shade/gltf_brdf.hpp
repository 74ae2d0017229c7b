#pragma once

#include <raster/image/colour.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

// glTF 2.0's metallic-roughness BRDF exactly as its Appendix B writes it: Trowbridge-Reitz (GGX)
// distribution, Smith height-correlated visibility, Schlick Fresnel; the diffuse lobe Lambert's
// of c_diff = mix(base, black, metallic), weighted by 1 - F (doc/conventions.md#metallic-roughness).
namespace raster::gltf_brdf {

inline constexpr float kPi = 3.14159265358979F;
inline constexpr float kDielectricF0 = 0.04F;
// A mirror's distribution is a spike no sample meets: alpha is held at least this.
inline constexpr float kSmallestAlpha = 1e-3F;

// D: the share of microfacets facing h, alpha = roughness^2.
[[nodiscard]] inline float distribution(float n_dot_h, float alpha) noexcept {
    const float a2 = alpha * alpha;
    const float f = n_dot_h * n_dot_h * (a2 - 1.0F) + 1.0F;
    return a2 / (kPi * f * f);
}

// V = G / (4 |n.l| |n.v|), the height-correlated Smith form; 0 where both cosines are 0.
[[nodiscard]] inline float visibility(float n_dot_l, float n_dot_v, float alpha) noexcept {
    const float a2 = alpha * alpha;
    const float ggx_v = n_dot_l * std::sqrt(n_dot_v * n_dot_v * (1.0F - a2) + a2);
    const float ggx_l = n_dot_v * std::sqrt(n_dot_l * n_dot_l * (1.0F - a2) + a2);
    const float sum = ggx_v + ggx_l;
    return sum > 0.0F ? 0.5F / sum : 0.0F;
}

// Schlick's Fresnel for reflectance f0 at normal incidence and 1 at grazing.
[[nodiscard]] inline LinearRgb fresnel(LinearRgb f0, float v_dot_h) noexcept {
    const float m = std::clamp(1.0F - v_dot_h, 0.0F, 1.0F);
    const float m5 = m * m * m * m * m;
    return f0 + (LinearRgb{1.0F, 1.0F, 1.0F} - f0) * m5;
}

// The reflectance at normal incidence: 4 % for a dielectric, the base colour for a metal.
[[nodiscard]] inline LinearRgb f0_of(LinearRgb base, float metallic) noexcept {
    return LinearRgb{kDielectricF0, kDielectricF0, kDielectricF0} * (1.0F - metallic) + base * metallic;
}

// f(l, v) for unit n, v and l on the same side (0 below the horizon of either), roughness in [0, 1].
[[nodiscard]] inline LinearRgb brdf(LinearRgb base, float metallic, float roughness, glm::vec3 n, glm::vec3 v,
                                    glm::vec3 l) noexcept {
    const float n_dot_l = glm::dot(n, l), n_dot_v = glm::dot(n, v);
    if (!(n_dot_l > 0.0F) || !(n_dot_v > 0.0F)) return {};
    const glm::vec3 sum = l + v;
    const float length = glm::length(sum);
    if (!(length > 0.0F)) return {};
    const glm::vec3 h = sum / length;
    const float alpha = std::max(roughness * roughness, kSmallestAlpha);
    const LinearRgb f = fresnel(f0_of(base, metallic), std::max(0.0F, glm::dot(v, h)));
    const LinearRgb c_diff = base * (1.0F - metallic);
    const float specular = distribution(std::max(0.0F, glm::dot(n, h)), alpha) * visibility(n_dot_l, n_dot_v, alpha);
    return (LinearRgb{1.0F, 1.0F, 1.0F} - f) * c_diff * (1.0F / kPi) + f * specular;
}

}  // namespace raster::gltf_brdf
