#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

// PNG files, for stills and numbered animation frames that other tools (ffmpeg, page builders)
// take in. Failures throw std::runtime_error with a one-line reason.
namespace raster {

// The bytes of an 8-bit PNG file of the image: RGB, or RGBA when `alpha` (one byte per pixel,
// 255 opaque) is given.
[[nodiscard]] std::vector<std::uint8_t> encode_png(const Framebuffer& image, std::span<const std::uint8_t> alpha = {});

struct DecodedPng {
    Framebuffer image;
    std::vector<std::uint8_t> alpha;  // one byte per pixel; all 255 for a file without alpha
};

// Decodes PNG bytes to 8-bit sRGB and alpha; refuses more than `max_pixels` pixels before
// decoding them.
[[nodiscard]] DecodedPng decode_png(std::span<const std::uint8_t> bytes, std::size_t max_pixels);

}  // namespace raster
