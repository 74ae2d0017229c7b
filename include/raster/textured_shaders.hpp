#pragma once

#include <raster/colour.hpp>
#include <raster/linear_lighting.hpp>
#include <raster/shaders.hpp>
#include <raster/texture.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// Shaders whose diffuse colour comes from a texture (or, without one, from the material):
// the texture's linear colour times the material's diffuse colour, as OBJ's map_Kd and Kd
// combine (doc/conventions.md#textures). Their pixel stage takes the Varying's change per pixel,
// from which trilinear filtering picks a mip level.
namespace raster {

// The diffuse colour at a texture coordinate: the material's, times the texture's if any.
struct DiffuseSource {
    LinearRgb colour;
    const Texture* texture = nullptr;
    Sampler sampler{};

    [[nodiscard]] LinearRgb at(glm::vec2 uv, const UvFootprint& footprint) const noexcept {
        return texture == nullptr ? colour : colour * texture->sample(uv, footprint, sampler);
    }
};

// No light at all: the diffuse colour as it is, the mode for exact comparisons with other renderers.
struct UnlitShader {
    using Varying = glm::vec2;
    static constexpr bool kFacetNormal = false;
    DiffuseSource diffuse;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return corner.uv; }
    [[nodiscard]] Rgb pixel(const Varying& uv, const Varying& per_x, const Varying& per_y) const noexcept {
        return srgb_from_linear(diffuse.at(uv, {per_x, per_y}));
    }
};

// Light received at the corners (or once per facet), interpolated, and the texture read at
// every pixel: emissive + texture * diffuse light + specular light.
template <bool FacetNormal>
struct TexturedLightShader {
    struct Varying {
        float diffuse;
        LinearRgb specular;
        glm::vec2 uv;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept {
            return {x.diffuse + y.diffuse, x.specular + y.specular, x.uv + y.uv};
        }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept {
            return {x.diffuse - y.diffuse, x.specular - y.specular, x.uv - y.uv};
        }
        friend Varying operator*(const Varying& x, float k) noexcept { return {x.diffuse * k, x.specular * k, x.uv * k}; }
    };
    static constexpr bool kFacetNormal = FacetNormal;
    const LinearLighting* lighting;
    DiffuseSource diffuse;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        const LinearLighting::Received light = lighting->received(corner.position, corner.normal);
        return {light.diffuse, lighting->material().specular * light.specular, corner.uv};
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        const LinearRgb albedo = diffuse.at(v.uv, {per_x.uv, per_y.uv});
        return srgb_from_linear(lighting->material().emissive + albedo * v.diffuse + v.specular);
    }
};
using TexturedFlatShader = TexturedLightShader<true>;
using TexturedGouraudShader = TexturedLightShader<false>;

// Position, normal and texture coordinate interpolated; lit and textured at every pixel.
struct TexturedPhongShader {
    struct Varying {
        glm::vec3 position;
        glm::vec3 normal;
        glm::vec2 uv;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept {
            return {x.position + y.position, x.normal + y.normal, x.uv + y.uv};
        }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept {
            return {x.position - y.position, x.normal - y.normal, x.uv - y.uv};
        }
        friend Varying operator*(const Varying& x, float k) noexcept { return {x.position * k, x.normal * k, x.uv * k}; }
    };
    static constexpr bool kFacetNormal = false;
    const LinearLighting* lighting;
    DiffuseSource diffuse;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return {corner.position, corner.normal, corner.uv}; }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        const LinearRgb albedo = diffuse.at(v.uv, {per_x.uv, per_y.uv});
        return srgb_from_linear(lighting->shade(v.position, unit_or_zero(v.normal), albedo));
    }
};

}  // namespace raster
