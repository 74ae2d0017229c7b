#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/image/lanes.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace raster {

// A light infinitely far away: `toward` points from the surface to the light (any length).
struct DirectionalLight {
    glm::vec3 toward;
    float intensity = 1.0F;
};

// A surface in 8-bit intensity: a base colour scaled by one intensity,
// I = ambient + diffuse * sum over lights of intensity * (max(0, n.l) + max(0, n.h)^shininess),
// the specular term only when a shininess is given; a negative or NaN shininess counts as 0
// (doc/conventions.md#light).
struct IntensityMaterial {
    Rgb base;
    float ambient = 0.0F;
    float diffuse = 1.0F;
    std::optional<float> shininess;

    // Lambert plus ambient, the diffuse share being what the ambient leaves.
    [[nodiscard]] static IntensityMaterial matte(Rgb base, float ambient) {
        return {base, ambient, 1.0F - ambient, {}};
    }
    // Blinn-Phong on top.
    [[nodiscard]] static IntensityMaterial shiny(Rgb base, float ambient, float shininess) {
        return {base, ambient, 1.0F - ambient, shininess};
    }
};

// cosine^shininess for the Blinn-Phong highlight; no shininess means no highlight. A negative or
// NaN shininess counts as 0 (pow(0, -s) would be infinite).
class SpecularPower {
public:
    explicit SpecularPower(std::optional<float> shininess) noexcept;
    [[nodiscard]] bool enabled() const noexcept { return exponent_.has_value(); }
    // The exponent, when there is one, and whether it is whole (then raised by squaring).
    [[nodiscard]] float exponent() const noexcept { return exponent_.value_or(0.0F); }
    [[nodiscard]] std::optional<unsigned> whole() const noexcept { return whole_; }
    // Inline: it runs at every pixel of a Phong surface, once per light.
    [[nodiscard]] float operator()(float cosine) const noexcept {
        // A dot of unit vectors can exceed 1 by a rounding; above 1 a huge exponent would overflow.
        if (!whole_) return std::pow(std::min(cosine, 1.0F), *exponent_);
        // Repeated squaring, several times faster than std::pow (the original's powi does the same).
        float result = 1.0F;
        for (unsigned n = *whole_; n != 0; n >>= 1U, cosine *= cosine) {
            if ((n & 1U) != 0) result *= cosine;
        }
        return result;
    }

private:
    std::optional<float> exponent_;
    std::optional<unsigned> whole_;
};

// A light ready for shading: unit direction toward it and the Blinn half vector for a viewer
// along `to_eye`; an unusable direction (zero, NaN, infinite) leaves both zero, so the light
// adds nothing.
struct PreparedLight {
    glm::vec3 toward;
    glm::vec3 half;
    float intensity;
};
[[nodiscard]] PreparedLight prepare_light(const DirectionalLight& light, glm::vec3 to_eye) noexcept;

// Everything the shaders need that is the same for every pixel of a mesh.
struct IntensityLighting {
    IntensityMaterial material;
    std::vector<PreparedLight> lights;

    // `to_eye` is the unit vector toward the viewer; orthographic, so one for the whole image.
    IntensityLighting(const IntensityMaterial& material, std::span<const DirectionalLight> lights, glm::vec3 to_eye);

    // The intensity for a unit normal (zero stands for "no normal": ambient only). Inline
    // because it runs at every pixel of a Phong surface.
    [[nodiscard]] float intensity(glm::vec3 normal) const noexcept {
        if (glm::dot(normal, normal) == 0.0F) return material.ambient;  // no normal: no direct light
        float lit = 0.0F;
        for (const PreparedLight& light : lights) {
            float received = std::max(0.0F, glm::dot(normal, light.toward));
            if (specular_.enabled()) received += specular_(std::max(0.0F, glm::dot(normal, light.half)));
            lit += light.intensity * received;
        }
        return material.ambient + material.diffuse * lit;
    }
    // intensity(unit_or_zero(normal)) at `count` normals at once, in SIMD lanes, each lane equal to it bit for bit.
    void intensity_lanes(const LaneVec3& normals, LaneFloats& out, int count) const noexcept;

private:
    SpecularPower specular_;
};

// base * intensity per channel, rounded to nearest (halves up) and clamped to 0..255; NaN
// gives black. Inline, like intensity(), for the per-pixel path.
[[nodiscard]] inline Rgb scaled_colour(Rgb base, float intensity) noexcept {
    const auto channel = [intensity](std::uint8_t c) -> std::uint8_t {
        const float v = static_cast<float>(c) * intensity;
        if (!(v > 0.0F)) return 0;  // negative or NaN
        if (v >= 255.0F) return 255;
        const auto whole = static_cast<std::uint8_t>(v);  // truncation is floor here
        return v - static_cast<float>(whole) >= 0.5F ? static_cast<std::uint8_t>(whole + 1) : whole;
    };
    return {channel(base.r), channel(base.g), channel(base.b)};
}

// scaled_colour(base, intensity[i]) for lane i of the first out.size(), in SIMD lanes.
void scaled_colours(Rgb base, const LaneFloats& intensity, std::span<Rgb> out) noexcept;

}  // namespace raster
