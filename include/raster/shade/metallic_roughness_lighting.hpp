#pragma once

#include <raster/image/colour.hpp>
#include <raster/shade/intensity_lighting.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/metallic_roughness.hpp>
#include <raster/shade/surroundings.hpp>
#include <raster/shade/texture.hpp>

#include <optional>
#include <span>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

// A metallic-roughness surface lit by directional and point lights through glTF's BRDF and by
// its surroundings through the split sum (doc/conventions.md#metallic-roughness).
namespace raster {

// What one pixel of the surface knows: its world position and normal, its texture coordinate,
// its vertex colour, how position and texture coordinate change per pixel step (for the mip
// level, and for the normal map's tangent frame where there is no tangent), and the interpolated
// vertex tangent (doc/conventions.md#normal-maps).
struct MaterialPoint {
    glm::vec3 position;
    glm::vec3 normal;  // any length; zero for "no normal": emissive light only
    glm::vec2 uv{0.0F};
    LinearRgb tint{1.0F, 1.0F, 1.0F};
    glm::vec3 position_per_x{0.0F}, position_per_y{0.0F};
    UvFootprint footprint{};
    glm::vec4 tangent{0.0F};  // any length, w's sign the handedness; zero for none
};

// The material as read at one point, its maps applied to its factors.
struct MaterialSample {
    LinearRgb base_colour;
    float metallic;
    float roughness;
    float occlusion;  // 1 + strength (texel - 1): what reaches the point of the surrounding light
    LinearRgb emissive;
    glm::vec3 normal;  // unit, the normal map applied; zero for none
};

class MetallicRoughnessLighting {
public:
    // A directional light's intensity is the light a white matte surface facing it returns,
    // as in raster's Phong (pi times glTF's irradiance); `surroundings` may be null (none).
    MetallicRoughnessLighting(const MetallicRoughness& material, Sampler sampler, const Surroundings* surroundings,
                              std::span<const DirectionalLight> directional, std::span<const PointLight> points,
                              glm::vec3 to_eye, std::optional<glm::vec3> eye = std::nullopt);

    [[nodiscard]] const MetallicRoughness& material() const noexcept { return material_; }
    // The material's maps read at the point and applied to its factors.
    [[nodiscard]] MaterialSample sample(const MaterialPoint& point) const noexcept;
    // The light leaving the point toward the viewer, in linear light; never NaN.
    [[nodiscard]] LinearRgb shade(const MaterialPoint& point) const noexcept {
        return shade(point.position, sample(point));
    }
    [[nodiscard]] LinearRgb shade(glm::vec3 position, const MaterialSample& surface) const noexcept;

private:
    MetallicRoughness material_;
    Sampler sampler_;
    const Surroundings* surroundings_;
    std::vector<PreparedLight> directional_;
    std::vector<PreparedPointLight> points_;
    glm::vec3 to_eye_;
    std::optional<glm::vec3> eye_;
};

}  // namespace raster
