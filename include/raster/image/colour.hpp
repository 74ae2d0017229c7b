#pragma once

#include <raster/image/framebuffer.hpp>

#include <array>
#include <cstdint>

// Colours in linear light, and the exact sRGB transfer functions between them and the 8-bit
// sRGB bytes of the framebuffer (IEC 61966-2-1; doc/conventions.md#colour).
namespace raster {

// A colour in linear light: light adds and scales here. Displayable colours lie in [0, 1];
// sums may exceed 1 and are clamped only when written as bytes.
struct LinearRgb {
    float r = 0.0F;
    float g = 0.0F;
    float b = 0.0F;

    friend constexpr LinearRgb operator+(LinearRgb x, LinearRgb y) noexcept {
        return {x.r + y.r, x.g + y.g, x.b + y.b};
    }
    friend constexpr LinearRgb operator-(LinearRgb x, LinearRgb y) noexcept {
        return {x.r - y.r, x.g - y.g, x.b - y.b};
    }
    friend constexpr LinearRgb operator*(LinearRgb x, float k) noexcept { return {x.r * k, x.g * k, x.b * k}; }
    friend constexpr LinearRgb operator*(LinearRgb x, LinearRgb y) noexcept {
        return {x.r * y.r, x.g * y.g, x.b * y.b};
    }
    friend constexpr bool operator==(LinearRgb, LinearRgb) = default;
};

// The standard's decoding of one channel, c in [0, 1]: c / 12.92 up to 0.04045, else
// ((c + 0.055) / 1.055)^2.4.
[[nodiscard]] double linear_from_srgb_channel(double encoded) noexcept;
// Its inverse: 12.92 v up to 0.0031308, else 1.055 v^(1/2.4) - 0.055.
[[nodiscard]] double srgb_from_linear_channel(double linear) noexcept;

// Each sRGB byte b in linear light, linear_from_srgb_channel(b / 255) as a float: a table for
// loops that decode many bytes (the resolve of anti-aliased samples).
[[nodiscard]] const std::array<float, 256>& linear_from_srgb_bytes() noexcept;
// A byte colour in linear light.
[[nodiscard]] LinearRgb linear_from_srgb(Rgb colour) noexcept;

// The nearest sRGB byte per channel, exactly round(255 * srgb_from_linear_channel(v)) with
// halves up, for every float: v at or below 0 (and NaN) is 0, at or above 1 is 255. A 4096-entry
// table says where to start and the 255 exact decision thresholds finish, which the lab measured
// against the alternatives (doc/lab/README.md#colour-encoding).
[[nodiscard]] Rgb srgb_from_linear(LinearRgb colour) noexcept;
// The same for one channel.
[[nodiscard]] std::uint8_t srgb_byte_from_linear(float linear) noexcept;

}  // namespace raster
