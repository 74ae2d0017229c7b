#pragma once

#include <cstdint>
#include <span>
#include <string_view>

// The header reader that runs before any decoder: it names an image file's format, reads its
// size and says whether the file ends early, so that no decoder sees a file it would misread.
namespace raster::detail {

enum class ImageFormat { png, jpeg, tga, bmp, webp };

struct ImageHeader {
    ImageFormat format;
    int width;  // as the header says (may be huge: callers check limits)
    int height;
    bool truncated;  // the data ends before the header (or the format's structure) says it should
};

// The format's name as users know it: "PNG", "JPEG", "TGA", "BMP", "WebP".
[[nodiscard]] std::string_view format_name(ImageFormat format);

// Whether the first bytes (up to 32 of them) could begin an image raster reads: the signature
// check made before a file is read whole. TGA has no signature: a plausible 18-byte TGA header
// is accepted (colour-map type 0 or 1, image type 1, 2, 3, 9, 10 or 11, pixel depth 8, 15, 16,
// 24 or 32, and a colour map exactly when the type is colour-mapped, as stb_image requires).
[[nodiscard]] bool begins_like_image(std::span<const std::uint8_t> head);

// Reads format, size and completeness from an image file's bytes. Throws std::runtime_error with
// a one-line reason in plain words when the bytes are no image raster reads or the header itself
// is broken, e.g. "not a PNG, JPEG, TGA, BMP or WebP image", "the PNG header is cut short" or
// "a GIF image; raster reads PNG, JPEG, TGA, BMP and WebP".
[[nodiscard]] ImageHeader read_image_header(std::span<const std::uint8_t> bytes);

}  // namespace raster::detail
