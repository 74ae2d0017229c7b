#pragma once

#include <raster/geometry/mesh.hpp>
#include <raster/image/colour.hpp>
#include <raster/image/lanes.hpp>
#include <raster/rasterize/shader.hpp>
#include <raster/shade/intensity_lighting.hpp>
#include <raster/shade/linear_lighting.hpp>

#include <span>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

// The library's untextured shaders, each a Shader of the rasterizer (raster/rasterize/shader.hpp).
namespace raster {

// Lights the corners and interpolates the intensity; with the facet normal at every corner
// that is one intensity per facet.
template <bool FacetNormal>
struct IntensityShader {
    using Varying = float;
    static constexpr bool kFacetNormal = FacetNormal;
    const IntensityLighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return lighting->intensity(corner.normal); }
    [[nodiscard]] Rgb pixel(Varying intensity) const noexcept {
        return scaled_colour(lighting->material.base, intensity);
    }
    // pixel() at up to kLanes intensities at once, in SIMD lanes.
    void pixels(std::span<const Varying> intensities, std::span<Rgb> out) const noexcept {
        LaneFloats lanes{};
        for (std::size_t i = 0; i < intensities.size(); ++i) lanes[i] = intensities[i];
        scaled_colours(lighting->material.base, lanes, out.first(intensities.size()));
    }
};

// One intensity per facet from its normal.
using FlatShader = IntensityShader<true>;
// Intensity at the corners, interpolated across the facet.
using GouraudShader = IntensityShader<false>;

// Normals interpolated and renormalised, lit at every pixel.
struct PhongShader {
    using Varying = glm::vec3;
    static constexpr bool kFacetNormal = false;
    const IntensityLighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return corner.normal; }
    [[nodiscard]] Rgb pixel(const Varying& normal) const noexcept {
        return scaled_colour(lighting->material.base, lighting->intensity(unit_or_zero(normal)));
    }
    // pixel() at up to kLanes normals at once, lit in SIMD lanes.
    void pixels(std::span<const Varying> normals, std::span<Rgb> out) const noexcept {
        LaneVec3 lanes;
        for (std::size_t i = 0; i < normals.size(); ++i) put_lane(lanes, i, normals[i]);
        LaneFloats intensity{};
        lighting->intensity_lanes(lanes, intensity, static_cast<int>(normals.size()));
        scaled_colours(lighting->material.base, intensity, out.first(normals.size()));
    }
};

// The same three in linear light: colours summed in linear light and encoded to sRGB
// at the pixel write.
template <bool FacetNormal>
struct LinearColourShader {
    using Varying = LinearRgb;
    static constexpr bool kFacetNormal = FacetNormal;
    const LinearLighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept {
        return lighting->shade(corner.position, corner.normal);
    }
    [[nodiscard]] Rgb pixel(const Varying& colour) const noexcept { return srgb_from_linear(colour); }
    // pixel() at up to kLanes colours at once.
    void pixels(std::span<const Varying> colours, std::span<Rgb> out) const noexcept {
        LaneRgb lanes;
        for (std::size_t i = 0; i < colours.size(); ++i) put_lane(lanes, i, colours[i]);
        srgb_from_linear(lanes, out.first(colours.size()));
    }
};

using LinearFlatShader = LinearColourShader<true>;
// Lights the corners and interpolates their colours.
using LinearGouraudShader = LinearColourShader<false>;

// World position and normal interpolated, lit at every pixel: point lights need the position.
struct LinearPhongShader {
    using Varying = SurfacePoint;
    static constexpr bool kFacetNormal = false;
    const LinearLighting* lighting;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return {corner.position, corner.normal}; }
    [[nodiscard]] Rgb pixel(const Varying& point) const noexcept {
        return srgb_from_linear(lighting->shade(point.position, unit_or_zero(point.normal)));
    }
    // pixel() at up to kLanes points at once, in SIMD lanes (raster/image/lanes.hpp).
    void pixels(std::span<const Varying> points, std::span<Rgb> out) const noexcept {
        LaneVec3 positions, normals;
        LaneRgb diffuse;
        for (std::size_t i = 0; i < points.size(); ++i) {
            put_lane(positions, i, points[i].position), put_lane(normals, i, points[i].normal);
            put_lane(diffuse, i, lighting->material().diffuse);
        }
        lighting->shade_lanes(positions, normals, diffuse, out.first(points.size()));
    }
};

}  // namespace raster
