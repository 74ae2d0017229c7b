#pragma once

#include <raster/image/colour.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/shaders.hpp>
#include <raster/shade/texture.hpp>
#include <raster/shade/texture_transform.hpp>

#include <span>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

// Shaders whose diffuse colour comes from a texture (or, without one, from the material):
// the texture's linear colour times the material's diffuse colour, as OBJ's map_Kd and Kd
// combine (doc/conventions.md#textures), and, when Tinted, times the corners' colours
// interpolated (doc/conventions.md#vertex-colours). Their pixel stage takes the Varying's change
// per pixel, from which trilinear filtering picks a mip level.
namespace raster {

// The corners' colour carried to the pixel when a mesh has vertex colours, and nothing (no
// storage, no arithmetic) when it has none.
template <bool Tinted>
struct Tint {
    LinearRgb colour;
    explicit Tint(LinearRgb corner) noexcept : colour(corner) {}
    Tint() noexcept = default;
    friend Tint operator+(const Tint& x, const Tint& y) noexcept { return Tint(x.colour + y.colour); }
    friend Tint operator-(const Tint& x, const Tint& y) noexcept { return Tint(x.colour - y.colour); }
    friend Tint operator*(const Tint& x, float k) noexcept { return Tint(x.colour * k); }
    [[nodiscard]] LinearRgb tinted(LinearRgb albedo) const noexcept { return albedo * colour; }
};
template <>
struct Tint<false> {
    explicit Tint(LinearRgb /*corner*/) noexcept {}
    Tint() noexcept = default;
    friend Tint operator+(const Tint&, const Tint&) noexcept { return {}; }
    friend Tint operator-(const Tint&, const Tint&) noexcept { return {}; }
    friend Tint operator*(const Tint&, float) noexcept { return {}; }
    [[nodiscard]] static LinearRgb tinted(LinearRgb albedo) noexcept { return albedo; }
};

// The diffuse colour at a texture coordinate: the material's, times the texture's if any, read
// where `transform` moves the coordinate (doc/conventions.md#texture-transform).
struct DiffuseSource {
    LinearRgb colour;
    const Texture* texture = nullptr;
    Sampler sampler{};
    TextureTransform transform{};

    [[nodiscard]] LinearRgb at(glm::vec2 uv, const UvFootprint& footprint) const noexcept {
        if (texture == nullptr) return colour;
        if (transform.identity()) return colour * texture->sample(uv, footprint, sampler);
        const MovedUv moved = moved_uv(transform, uv, footprint);
        return colour * texture->sample(moved.uv, moved.footprint, sampler);
    }
    // at() for the first `count` lanes of `uvs`.
    void at_lanes(const LaneUvs& uvs, LaneRgb& out, int count) const noexcept {
        if (texture != nullptr && transform.identity()) texture->sample_lanes(uvs, sampler, out, count);
        if (texture != nullptr && !transform.identity())
            texture->sample_lanes(moved_lanes(transform, uvs, count), sampler, out, count);
        for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
            const LinearRgb read = texture == nullptr ? colour : colour * LinearRgb{out.r[i], out.g[i], out.b[i]};
            put_lane(out, i, read);
        }
    }
};

// The texture coordinates of up to kLanes Varyings and their changes per pixel, side by side.
template <typename Varying>
[[nodiscard]] LaneUvs lane_uvs(std::span<const Varying> v, std::span<const Varying> per_x,
                               std::span<const Varying> per_y) noexcept {
    LaneUvs uvs;
    for (std::size_t i = 0; i < v.size(); ++i) {
        uvs.u[i] = v[i].uv.x, uvs.v[i] = v[i].uv.y;
        uvs.u_per_x[i] = per_x[i].uv.x, uvs.v_per_x[i] = per_x[i].uv.y, uvs.u_per_y[i] = per_y[i].uv.x,
        uvs.v_per_y[i] = per_y[i].uv.y;
    }
    return uvs;
}

// No light at all: the diffuse colour as it is, the mode for exact comparisons with other renderers.
template <bool Tinted>
struct BasicUnlitShader {
    struct Varying {
        glm::vec2 uv;
        [[no_unique_address]] Tint<Tinted> tint;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept { return {x.uv + y.uv, x.tint + y.tint}; }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept { return {x.uv - y.uv, x.tint - y.tint}; }
        friend Varying operator*(const Varying& x, float k) noexcept { return {x.uv * k, x.tint * k}; }
    };
    static constexpr bool kFacetNormal = false;
    DiffuseSource diffuse;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        return {corner.uv, Tint<Tinted>(corner.colour)};
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        return srgb_from_linear(v.tint.tinted(diffuse.at(v.uv, {per_x.uv, per_y.uv})));
    }
    // pixel() at up to kLanes points at once, the texture read in lanes.
    void pixels(std::span<const Varying> v, std::span<const Varying> per_x, std::span<const Varying> per_y,
                std::span<Rgb> out) const noexcept {
        LaneRgb albedo;
        diffuse.at_lanes(lane_uvs(v, per_x, per_y), albedo, static_cast<int>(v.size()));
        for (std::size_t i = 0; i < v.size(); ++i)
            out[i] = srgb_from_linear(v[i].tint.tinted({albedo.r[i], albedo.g[i], albedo.b[i]}));
    }
};
using UnlitShader = BasicUnlitShader<false>;
using TintedUnlitShader = BasicUnlitShader<true>;

// Light received at the corners (or once per facet), interpolated, and the texture read at
// every pixel: emissive + texture * diffuse light + specular light.
template <bool FacetNormal, bool Tinted = false>
struct TexturedLightShader {
    struct Varying {
        float diffuse;
        LinearRgb specular;
        glm::vec2 uv;
        [[no_unique_address]] Tint<Tinted> tint;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept {
            return {x.diffuse + y.diffuse, x.specular + y.specular, x.uv + y.uv, x.tint + y.tint};
        }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept {
            return {x.diffuse - y.diffuse, x.specular - y.specular, x.uv - y.uv, x.tint - y.tint};
        }
        friend Varying operator*(const Varying& x, float k) noexcept {
            return {x.diffuse * k, x.specular * k, x.uv * k, x.tint * k};
        }
    };
    static constexpr bool kFacetNormal = FacetNormal;
    const LinearLighting* lighting;
    DiffuseSource diffuse;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        const LinearLighting::Received light = lighting->received(corner.position, corner.normal);
        return {light.diffuse, lighting->material().specular * light.specular, corner.uv, Tint<Tinted>(corner.colour)};
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        const LinearRgb albedo = v.tint.tinted(diffuse.at(v.uv, {per_x.uv, per_y.uv}));
        return srgb_from_linear(lighting->material().emissive + albedo * v.diffuse + v.specular);
    }
    // pixel() at up to kLanes points at once, the texture read in lanes.
    void pixels(std::span<const Varying> v, std::span<const Varying> per_x, std::span<const Varying> per_y,
                std::span<Rgb> out) const noexcept {
        LaneRgb read;
        diffuse.at_lanes(lane_uvs(v, per_x, per_y), read, static_cast<int>(v.size()));
        for (std::size_t i = 0; i < v.size(); ++i) {
            const LinearRgb albedo = v[i].tint.tinted({read.r[i], read.g[i], read.b[i]});
            out[i] = srgb_from_linear(lighting->material().emissive + albedo * v[i].diffuse + v[i].specular);
        }
    }
};
using TexturedFlatShader = TexturedLightShader<true>;
using TexturedGouraudShader = TexturedLightShader<false>;

// Position, normal and texture coordinate interpolated; lit and textured at every pixel.
template <bool Tinted>
struct BasicTexturedPhongShader {
    struct Varying {
        glm::vec3 position;
        glm::vec3 normal;
        glm::vec2 uv;
        [[no_unique_address]] Tint<Tinted> tint;
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
    static constexpr bool kFacetNormal = false;
    const LinearLighting* lighting;
    DiffuseSource diffuse;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        return {corner.position, corner.normal, corner.uv, Tint<Tinted>(corner.colour)};
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x, const Varying& per_y) const noexcept {
        const LinearRgb albedo = v.tint.tinted(diffuse.at(v.uv, {per_x.uv, per_y.uv}));
        return srgb_from_linear(lighting->shade(v.position, unit_or_zero(v.normal), albedo));
    }
    // pixel() at up to kLanes points at once, in SIMD lanes.
    void pixels(std::span<const Varying> v, std::span<const Varying> per_x, std::span<const Varying> per_y,
                std::span<Rgb> out) const noexcept {
        LaneVec3 positions, normals;
        for (std::size_t i = 0; i < v.size(); ++i)
            put_lane(positions, i, v[i].position), put_lane(normals, i, v[i].normal);
        LaneRgb albedo;
        diffuse.at_lanes(lane_uvs(v, per_x, per_y), albedo, static_cast<int>(v.size()));
        if constexpr (Tinted) {
            for (std::size_t i = 0; i < v.size(); ++i)
                put_lane(albedo, i, v[i].tint.tinted({albedo.r[i], albedo.g[i], albedo.b[i]}));
        }
        lighting->shade_lanes(positions, normals, albedo, out.first(v.size()));
    }
};

using TexturedPhongShader = BasicTexturedPhongShader<false>;

// The same with vertex colours: the mesh's corner colours interpolated, multiplying the diffuse colour.
using TintedFlatShader = TexturedLightShader<true, true>;
using TintedGouraudShader = TexturedLightShader<false, true>;
using TintedPhongShader = BasicTexturedPhongShader<true>;

// A mesh without colours pays nothing for them: its Varyings hold no tint.
static_assert(sizeof(TexturedPhongShader::Varying) == sizeof(float) * 8);
static_assert(sizeof(TexturedFlatShader::Varying) == sizeof(float) * 6);
static_assert(sizeof(UnlitShader::Varying) == sizeof(float) * 2);

}  // namespace raster
