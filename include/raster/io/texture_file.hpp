#pragma once

#include <raster/io/input_file.hpp>
#include <raster/shade/texture.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

// Textures read from image files: PNG, JPEG, TGA and BMP through stb_image, and WebP.
namespace raster {

// The most texels a texture file may hold, 4096 x 4096 or the same count in another shape;
// larger images are refused from their header, before anything is decoded.
inline constexpr std::size_t kMaxTextureTexels = std::size_t{4096} * 4096;
// The largest texture file read, in bytes: enough for any image within the texel limit.
inline constexpr std::uintmax_t kMaxTextureFileBytes = std::uintmax_t{256} << 20;

// Decodes an image held in memory (WebP by its signature, PNG, JPEG, TGA and BMP through stb_image),
// keeping red, green and blue as sRGB bytes and dropping alpha. Throws std::runtime_error with a
// one-line reason.
[[nodiscard]] Texture decode_texture(std::span<const std::uint8_t> bytes, std::size_t max_texels = kMaxTextureTexels);

// Reads and decodes an image file; errors name the file: "wood.png: not a PNG, JPEG, ...".
// With `confine` set (by confinement_root), a file outside that directory is refused; the file
// read is appended to `sources` when given.
[[nodiscard]] Texture read_texture(const std::filesystem::path& path, std::size_t max_texels = kMaxTextureTexels,
                                   const std::filesystem::path& confine = {},
                                   std::vector<InputRecord>* sources = nullptr);

}  // namespace raster
