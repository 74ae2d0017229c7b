#pragma once

#include <raster/lighting.hpp>
#include <raster/mesh.hpp>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

// A shader is two stages around the one rasterizer (doc/conventions.md#shading): vertex() turns
// a corner into a Varying, which the rasterizer interpolates linearly across the triangle, and
// pixel() turns the interpolated Varying into a colour. kFacetNormal asks for the facet's
// normal at every corner instead of the vertex normals.
namespace raster {

// What the vertex stage sees of one corner, in world space.
struct Corner {
    glm::vec3 position;
    glm::vec3 normal;
};

// Lights the corners and interpolates the intensity; with the facet normal at every corner
// that is one intensity per facet.
template <bool FacetNormal>
struct IntensityShader {
    using Varying = float;
    static constexpr bool kFacetNormal = FacetNormal;
    const Lighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return lighting->intensity(corner.normal); }
    [[nodiscard]] Rgb pixel(Varying intensity) const noexcept { return scaled_colour(lighting->material.base, intensity); }
};

// One intensity per facet from its normal: 0.0.8 to 0.0.11.
using FlatShader = IntensityShader<true>;
// Intensity at the corners, interpolated across the facet: 0.0.12 and 0.0.13.
using GouraudShader = IntensityShader<false>;

// Normals interpolated and renormalised, lit at every pixel: 0.0.15 onward.
struct PhongShader {
    using Varying = glm::vec3;
    static constexpr bool kFacetNormal = false;
    const Lighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return corner.normal; }
    [[nodiscard]] Rgb pixel(const Varying& normal) const noexcept {
        return scaled_colour(lighting->material.base, lighting->intensity(unit_or_zero(normal)));
    }
};

}  // namespace raster
