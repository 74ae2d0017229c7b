#pragma once

#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/shader.hpp>
#include <raster/shade/metallic_roughness_lighting.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

// The metallic-roughness material shaded at every pixel (doc/conventions.md#metallic-roughness):
// position, normal, texture coordinate, vertex colour and tangent interpolated, the maps read and
// glTF's BRDF evaluated per pixel, pixel by pixel (no SIMD lanes yet). With FacetNormal every pixel
// of a facet takes the facet's normal, and the normal map is not applied.
namespace raster {

template <bool FacetNormal>
struct MetallicRoughnessShader {
    struct Varying {
        glm::vec3 position;
        glm::vec3 normal;
        glm::vec2 uv;
        LinearRgb tint;
        glm::vec4 tangent;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept {
            return {x.position + y.position, x.normal + y.normal, x.uv + y.uv, x.tint + y.tint, x.tangent + y.tangent};
        }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept {
            return {x.position - y.position, x.normal - y.normal, x.uv - y.uv, x.tint - y.tint, x.tangent - y.tangent};
        }
        friend Varying operator*(const Varying& x, float k) noexcept {
            return {x.position * k, x.normal * k, x.uv * k, x.tint * k, x.tangent * k};
        }
    };
    static constexpr bool kFacetNormal = FacetNormal;
    const MetallicRoughnessLighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        return {corner.position, corner.normal, corner.uv, corner.colour, corner.tangent};
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        const glm::vec3 no_change(0.0F);
        const MaterialPoint point{v.position,
                                  v.normal,
                                  v.uv,
                                  v.tint,
                                  FacetNormal ? no_change : per_x.position,
                                  FacetNormal ? no_change : per_y.position,
                                  {per_x.uv, per_y.uv},
                                  FacetNormal ? glm::vec4(0.0F) : v.tangent};
        return srgb_from_linear(lighting->shade(point));
    }
};
using MetallicRoughnessFlatShader = MetallicRoughnessShader<true>;
using MetallicRoughnessPhongShader = MetallicRoughnessShader<false>;

}  // namespace raster
