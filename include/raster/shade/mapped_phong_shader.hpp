#pragma once

#include <raster/geometry/mesh.hpp>
#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/shader.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/normal_map.hpp>
#include <raster/shade/phong_maps.hpp>
#include <raster/shade/textured_shaders.hpp>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// A Phong material whose specular, emissive or normal map is read at every pixel
// (doc/conventions.md#mtl-maps): lit per pixel whatever the shading method asks, pixel by pixel
// (no SIMD lanes), so that materials without these maps keep their faster shaders. With
// FacetNormal every pixel of a facet takes the facet's normal and the normal map is not applied.
namespace raster {

template <bool FacetNormal>
struct MappedPhongShader {
    struct Varying {
        glm::vec3 position;
        glm::vec3 normal;
        glm::vec2 uv;
        LinearRgb tint;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept {
            return {x.position + y.position, x.normal + y.normal, x.uv + y.uv, x.tint + y.tint};
        }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept {
            return {x.position - y.position, x.normal - y.normal, x.uv - y.uv, x.tint - y.tint};
        }
        friend Varying operator*(const Varying& x, float k) noexcept {
            return {x.position * k, x.normal * k, x.uv * k, x.tint * k};
        }
    };
    static constexpr bool kFacetNormal = FacetNormal;
    const LinearLighting* lighting;
    DiffuseSource diffuse;
    const PhongMaps* maps;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        return {corner.position, corner.normal, corner.uv, corner.colour};
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        const UvFootprint footprint{per_x.uv, per_y.uv};
        const auto read = [&](const Texture& map) { return map.sample(v.uv, footprint, diffuse.sampler); };
        const LinearMaterial& material = lighting->material();
        glm::vec3 normal = unit_or_zero(v.normal);
        if (!FacetNormal && maps->normal && glm::dot(normal, normal) > 0.0F)
            normal = normal_mapped(normal, read(*maps->normal), 1.0F, glm::vec4(0.0F), per_x.position, per_y.position,
                                   footprint);
        const LinearLighting::Received light = lighting->received(v.position, normal);
        const LinearRgb specular = maps->specular ? material.specular * read(*maps->specular) : material.specular;
        const LinearRgb emissive = maps->emissive ? material.emissive * read(*maps->emissive) : material.emissive;
        const LinearRgb albedo = v.tint * diffuse.at(v.uv, footprint);
        return srgb_from_linear(emissive + albedo * light.diffuse + specular * light.specular);
    }
};
using MappedPhongFlatShader = MappedPhongShader<true>;
using MappedPhongSmoothShader = MappedPhongShader<false>;

}  // namespace raster
