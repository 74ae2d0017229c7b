#pragma once

#include <array>
#include <glm/vec3.hpp>

// The nine real spherical harmonics of bands 0 to 2, and the cosine lobe's convolution weights,
// for irradiance from radiance (Ramamoorthi and Hanrahan, "An efficient representation for
// irradiance environment maps", 2001).
namespace raster::detail {

[[nodiscard]] inline std::array<float, 9> spherical_harmonics(glm::vec3 d) noexcept {
    return {0.282095F,
            0.488603F * d.y,
            0.488603F * d.z,
            0.488603F * d.x,
            1.092548F * d.x * d.y,
            1.092548F * d.y * d.z,
            0.315392F * (3.0F * d.z * d.z - 1.0F),
            1.092548F * d.x * d.z,
            0.546274F * (d.x * d.x - d.y * d.y)};
}

// Irradiance E = sum A_band L_lm Y_lm: the clamped cosine's band weights pi, 2 pi / 3, pi / 4.
inline constexpr std::array<float, 9> kCosineBands = {3.14159265F, 2.09439510F, 2.09439510F, 2.09439510F, 0.78539816F,
                                                      0.78539816F, 0.78539816F, 0.78539816F, 0.78539816F};

}  // namespace raster::detail
