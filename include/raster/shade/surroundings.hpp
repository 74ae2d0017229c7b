#pragma once

#include <raster/image/colour.hpp>
#include <raster/shade/split_sum_table.hpp>

#include <array>
#include <functional>
#include <vector>
#include <glm/vec3.hpp>

// Light arriving from every direction around a scene, prefiltered once so that shading reads it
// in a few lookups (doc/conventions.md#surroundings): irradiance as nine spherical-harmonic
// coefficients, specular light as small latitude-longitude maps by roughness, and the split-sum table.
namespace raster {

// The radiance arriving from world direction `toward` (unit), in linear light.
using Radiance = std::function<LinearRgb(glm::vec3 toward)>;

// raster's built-in neutral studio, +y up: a bright ceiling, a soft horizon, a dark floor and two
// soft windows, grey throughout.
[[nodiscard]] LinearRgb studio_radiance(glm::vec3 toward) noexcept;

class Surroundings {
public:
    // Prefilters `radiance`, read at kSourceWidth x kSourceWidth / 2 directions.
    explicit Surroundings(const Radiance& radiance);
    // The built-in studio (studio_radiance()).
    [[nodiscard]] static Surroundings studio();

    // The light a white Lambertian surface facing unit `normal` reflects: irradiance / pi.
    [[nodiscard]] LinearRgb diffuse(glm::vec3 normal) const noexcept;
    // The radiance arriving about unit direction `reflected`, averaged over the GGX lobe of `roughness`.
    [[nodiscard]] LinearRgb specular(glm::vec3 reflected, float roughness) const noexcept;
    [[nodiscard]] const SplitSumTable& table() const noexcept { return table_; }

    static constexpr int kSourceWidth = 64;  // the radiance read at 64 x 32 directions
    static constexpr int kMapWidth = 32;     // each prefiltered level 32 x 16
    static constexpr int kLevels = 6;        // roughness 0, 0.2, ... 1

private:
    std::array<LinearRgb, 9> irradiance_{};       // spherical-harmonic coefficients, already convolved
    std::vector<std::vector<LinearRgb>> levels_;  // row-major, row 0 at +y
    SplitSumTable table_;
};

}  // namespace raster
