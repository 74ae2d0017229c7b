#include <raster/shade/gltf_brdf.hpp>
#include <raster/shade/surroundings.hpp>

#include "shade/spherical_harmonics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>

namespace raster {
namespace {

using gltf_brdf::kPi;

// The direction at the centre of texel (column, row) of a width x width / 2 latitude-longitude map, row 0 at +y.
glm::vec3 direction_of(int column, int row, int width) noexcept {
    const float theta = (static_cast<float>(row) + 0.5F) / static_cast<float>(width / 2) * kPi;
    const float phi = (static_cast<float>(column) + 0.5F) / static_cast<float>(width) * 2.0F * kPi;
    return {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
}

// A map read between its texel centres: wrapping in longitude, held at the poles.
LinearRgb bilinear(const std::vector<LinearRgb>& map, int width, glm::vec3 d) noexcept {
    const int height = width / 2;
    const float phi = std::atan2(d.z, d.x);
    const float u = (phi < 0.0F ? phi + 2.0F * kPi : phi) / (2.0F * kPi) * static_cast<float>(width) - 0.5F;
    const float v = std::acos(std::clamp(d.y, -1.0F, 1.0F)) / kPi * static_cast<float>(height) - 0.5F;
    const float uf = std::floor(u), vf = std::clamp(std::floor(v), 0.0F, static_cast<float>(height - 2));
    const float fu = u - uf, fv = std::clamp(v - vf, 0.0F, 1.0F);
    const int c0 = (static_cast<int>(uf) % width + width) % width, c1 = (c0 + 1) % width;
    const int r0 = static_cast<int>(vf), r1 = r0 + 1;
    const auto at = [&](int c, int r) { return map[static_cast<std::size_t>(r * width + c)]; };
    return (at(c0, r0) * (1.0F - fu) + at(c1, r0) * fu) * (1.0F - fv) +
           (at(c0, r1) * (1.0F - fu) + at(c1, r1) * fu) * fv;
}

}  // namespace

Surroundings::Surroundings(const Radiance& radiance) {
    constexpr int kWidth = kSourceWidth, kHeight = kSourceWidth / 2;
    struct Texel {
        glm::vec3 direction;
        LinearRgb radiance;
        float solid_angle;
    };
    std::vector<Texel> source;
    source.reserve(static_cast<std::size_t>(kWidth * kHeight));
    const float step = (2.0F * kPi / kWidth) * (kPi / kHeight);
    for (int row = 0; row < kHeight; ++row) {
        for (int column = 0; column < kWidth; ++column) {
            const glm::vec3 d = direction_of(column, row, kWidth);
            const LinearRgb l = radiance(d);
            const auto usable = [](float c) { return std::isfinite(c) ? std::max(c, 0.0F) : 0.0F; };
            source.push_back({d, {usable(l.r), usable(l.g), usable(l.b)}, step * std::sqrt(1.0F - d.y * d.y)});
        }
    }
    for (const Texel& t : source) {  // project onto the harmonics, convolved with the cosine, over pi
        const std::array<float, 9> y = detail::spherical_harmonics(t.direction);
        for (std::size_t k = 0; k < 9; ++k)
            irradiance_[k] = irradiance_[k] + t.radiance * (y[k] * t.solid_angle * detail::kCosineBands[k] / kPi);
    }
    for (int level = 0; level < kLevels; ++level) {
        const float roughness = static_cast<float>(level) / static_cast<float>(kLevels - 1);
        const float alpha = std::max(roughness * roughness, gltf_brdf::kSmallestAlpha);
        std::vector<LinearRgb>& map = levels_.emplace_back();
        for (int row = 0; row < kMapWidth / 2; ++row) {
            for (int column = 0; column < kMapWidth; ++column) {
                const glm::vec3 r = direction_of(column, row, kMapWidth);
                if (level == 0) {  // a mirror: the radiance itself
                    map.push_back(radiance(r));
                    continue;
                }
                // Karis's prefilter with n = v = r: the radiance weighted by D(n.h) n.l.
                LinearRgb sum{};
                float weights = 0.0F;
                for (const Texel& t : source) {
                    const float n_dot_l = glm::dot(r, t.direction);
                    if (!(n_dot_l > 0.0F)) continue;
                    const float n_dot_h = std::sqrt(0.5F * (1.0F + n_dot_l));  // h halfway between r and l
                    const float w = gltf_brdf::distribution(n_dot_h, alpha) * n_dot_l * t.solid_angle;
                    sum = sum + t.radiance * w;
                    weights += w;
                }
                map.push_back(weights > 0.0F ? sum * (1.0F / weights) : LinearRgb{});
            }
        }
    }
}

Surroundings Surroundings::studio() { return Surroundings(studio_radiance); }

LinearRgb Surroundings::diffuse(glm::vec3 normal) const noexcept {
    const std::array<float, 9> y = detail::spherical_harmonics(normal);
    LinearRgb sum{};
    for (std::size_t k = 0; k < 9; ++k) sum = sum + irradiance_[k] * y[k];
    return {std::max(sum.r, 0.0F), std::max(sum.g, 0.0F), std::max(sum.b, 0.0F)};  // ringing can dip below 0
}

LinearRgb Surroundings::specular(glm::vec3 reflected, float roughness) const noexcept {
    const float at = std::clamp(std::isfinite(roughness) ? roughness : 1.0F, 0.0F, 1.0F) * (kLevels - 1);
    const int lower = std::min(static_cast<int>(at), kLevels - 2);
    const float blend = at - static_cast<float>(lower);
    const LinearRgb a = bilinear(levels_[static_cast<std::size_t>(lower)], kMapWidth, reflected);
    const LinearRgb b = bilinear(levels_[static_cast<std::size_t>(lower) + 1], kMapWidth, reflected);
    return a * (1.0F - blend) + b * blend;
}

}  // namespace raster
