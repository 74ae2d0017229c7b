#pragma once

#include <raster/geometry/mesh.hpp>
#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/image/lanes.hpp>
#include <raster/shade/intensity_lighting.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

// Light in linear colour: explicit material colours, directional and point lights summed in
// linear light (doc/conventions.md#light-in-linear-colour).
namespace raster {

// A point light's attenuation with distance d: 1 / (constant + linear d + quadratic d^2).
struct Falloff {
    float constant = 1.0F;
    float linear = 0.0F;
    float quadratic = 0.0F;
};

// A light at a point, shining every way; its falloff scales both diffuse and specular light.
struct PointLight {
    glm::vec3 position;
    float intensity = 1.0F;
    Falloff falloff{};
};

// Phong colours in linear light, as three.js's MeshPhongMaterial has them: emissive light added
// once, diffuse and specular light per light; no shininess means no highlight.
struct LinearMaterial {
    LinearRgb emissive;
    LinearRgb diffuse;
    LinearRgb specular;
    std::optional<float> shininess;

    // The colours given as sRGB bytes (#RRGGBB), decoded to linear light.
    [[nodiscard]] static LinearMaterial from_srgb(Rgb emissive, Rgb diffuse, Rgb specular,
                                                  std::optional<float> shininess);
};

// raster-engine's Doom-like darkening: light received falls off linearly with view depth, from
// full at `start` to `floor` at `end` and beyond (emitted light is not darkened).
struct DepthDarkening {
    float start = 0.0F;
    float end = 1.0F;
    float floor = 0.0F;
    [[nodiscard]] float factor(float depth) const noexcept {
        if (!(depth > start)) return 1.0F;
        if (!(depth < end)) return floor;
        return 1.0F - (1.0F - floor) * (depth - start) / (end - start);
    }
};

// A point on a surface in world space: what a per-pixel shader needs for point lights.
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 normal;

    friend SurfacePoint operator+(const SurfacePoint& x, const SurfacePoint& y) noexcept {
        return {x.position + y.position, x.normal + y.normal};
    }
    friend SurfacePoint operator-(const SurfacePoint& x, const SurfacePoint& y) noexcept {
        return {x.position - y.position, x.normal - y.normal};
    }
    friend SurfacePoint operator*(const SurfacePoint& x, float k) noexcept { return {x.position * k, x.normal * k}; }
};

// A point light ready for shading; a light with a non-finite position or intensity, or a
// falloff that is negative, NaN or zero everywhere, never gets this far.
struct PreparedPointLight {
    glm::vec3 position;
    float intensity;
    Falloff falloff;
};

// Everything the linear-light shaders need that is the same for every pixel of a mesh.
class LinearLighting {
public:
    // `to_eye` is the unit vector toward the viewer of an orthographic view, one for the whole
    // image; with an `eye_position` (a perspective view) it is taken toward the eye at each point.
    // With an eye position, `darkening` dims the light a point receives by its view depth.
    LinearLighting(const LinearMaterial& material, std::span<const DirectionalLight> directional,
                   std::span<const PointLight> points, glm::vec3 to_eye,
                   std::optional<glm::vec3> eye_position = std::nullopt,
                   std::optional<DepthDarkening> darkening = std::nullopt);

    [[nodiscard]] const LinearMaterial& material() const noexcept { return material_; }

    // The colour leaving a surface point with unit normal `normal` toward the viewer (a zero
    // normal stands for "no normal": emissive only). Never NaN; may exceed 1 before the write
    // clamps it. Inline: it runs at every pixel of a Phong surface.
    [[nodiscard]] LinearRgb shade(glm::vec3 position, glm::vec3 normal) const noexcept {
        return shade(position, normal, material_.diffuse);
    }
    // The same with another diffuse colour in place of the material's: a texture's, say.
    [[nodiscard]] LinearRgb shade(glm::vec3 position, glm::vec3 normal, LinearRgb diffuse_colour) const noexcept {
        const Received light = received(position, normal);
        return material_.emissive + diffuse_colour * light.diffuse + material_.specular * light.specular;
    }
    // srgb_from_linear(shade(position, unit_or_zero(normal), diffuse colour)) at out.size() <=
    // kLanes points at once: the same operations in SIMD lanes, so each lane equals it bit for bit.
    void shade_lanes(const LaneVec3& positions, const LaneVec3& normals, const LaneRgb& diffuse_colours,
                     std::span<Rgb> out) const noexcept;

    // The light a surface point receives, before the material's colours: how much diffuse and
    // how much specular light. Zero for a zero normal.
    struct Received {
        float diffuse = 0.0F;
        float specular = 0.0F;
    };
    [[nodiscard]] Received received(glm::vec3 position, glm::vec3 normal) const noexcept {
        if (glm::dot(normal, normal) == 0.0F) return {};
        // Only highlights look toward the eye: a matte surface skips the square root.
        const glm::vec3 to_eye = eye_ && power_.enabled() ? toward_point(*eye_, position).unit : to_eye_;
        float diffuse = 0.0F, specular = 0.0F;
        for (const PreparedLight& light : directional_) {
            diffuse += light.intensity * std::max(0.0F, glm::dot(normal, light.toward));
            if (power_.enabled()) {
                const glm::vec3 half = eye_ ? unit_or_zero(light.toward + to_eye) : light.half;
                specular += light.intensity * power_(std::max(0.0F, glm::dot(normal, half)));
            }
        }
        for (const PreparedPointLight& light : points_) {
            const Toward toward = toward_point(light.position, position);
            if (!(toward.distance > 0.0F)) continue;  // at the light itself: no direction to light from
            const float arriving = attenuated(light, toward.distance);
            diffuse += arriving * std::max(0.0F, glm::dot(normal, toward.unit));
            if (power_.enabled()) {
                specular += arriving * power_(std::max(0.0F, glm::dot(normal, unit_or_zero(toward.unit + to_eye))));
            }
        }
        if (darkening_ && eye_) {
            const float dimmed = darkening_->factor(glm::dot(position - *eye_, -to_eye_));
            return {diffuse * dimmed, specular * dimmed};
        }
        return {diffuse, specular};
    }

    // Every light's factor is held within +-kBrightest, so that sums stay finite.
    static constexpr float kBrightest = 1e30F;

    // The factor a point light gives at distance d: intensity / (k_c + k_l d + k_q d^2), held
    // within +-kBrightest (a light on the surface with no constant term would be infinite).
    [[nodiscard]] static float attenuated(const PreparedPointLight& light, float distance) noexcept {
        const Falloff& f = light.falloff;
        // Zero terms stay zero at an infinite distance (0 * inf would be NaN).
        const float linear = f.linear == 0.0F ? 0.0F : f.linear * distance;
        const float quadratic = f.quadratic == 0.0F ? 0.0F : f.quadratic * distance * distance;
        const float denominator = f.constant + linear + quadratic;
        const float received = light.intensity / denominator;  // denominator > 0: falloffs are checked
        return std::clamp(received, -kBrightest, kBrightest);
    }

private:
    struct Toward {
        glm::vec3 unit;
        float distance;  // 0 when there is no direction
    };
    // The direction and distance from a surface point to a light; float arithmetic when the
    // squared distance fits a float, else double (huge or tiny offsets). Distance 0: none.
    [[nodiscard]] static Toward toward_point(glm::vec3 light, glm::vec3 surface) noexcept {
        const glm::vec3 offset = light - surface;
        const float squared = glm::dot(offset, offset);
        if (squared >= std::numeric_limits<float>::min() && squared < std::numeric_limits<float>::infinity()) {
            const float distance = std::sqrt(squared);
            return {offset / distance, distance};
        }
        return toward_point_precisely(light, surface);
    }
    [[nodiscard]] static Toward toward_point_precisely(glm::vec3 light, glm::vec3 surface) noexcept;

    LinearMaterial material_;
    std::vector<PreparedLight> directional_;
    std::vector<PreparedPointLight> points_;
    glm::vec3 to_eye_;
    std::optional<glm::vec3> eye_;
    SpecularPower power_;
    std::optional<DepthDarkening> darkening_;
};

}  // namespace raster
