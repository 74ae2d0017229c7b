#include <raster/io/png.hpp>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <png.h>

namespace raster {
namespace {

// libpng's simplified API keeps its state in the image: freed on every way out.
struct PngImage {
    png_image image;
    PngImage() {
        std::memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
    }
    ~PngImage() { png_image_free(&image); }
    PngImage(const PngImage&) = delete;
    PngImage& operator=(const PngImage&) = delete;

    [[nodiscard]] std::string why() const { return image.message[0] != '\0' ? image.message : "libpng failed"; }
};

}  // namespace

std::vector<std::uint8_t> encode_png(const Framebuffer& image, std::span<const std::uint8_t> alpha) {
    std::vector<std::uint8_t> rgba;
    if (!alpha.empty()) rgba = rgba_bytes(image, alpha);
    const std::uint8_t* pixels = alpha.empty() ? image.bytes().data() : rgba.data();
    PngImage png;
    png.image.width = static_cast<png_uint_32>(image.width());
    png.image.height = static_cast<png_uint_32>(image.height());
    png.image.format = alpha.empty() ? PNG_FORMAT_RGB : PNG_FORMAT_RGBA;
    // The first call measures, the second writes.
    png_alloc_size_t size = 0;
    if (!png_image_write_get_memory_size(png.image, size, 0, pixels, 0, nullptr))
        throw std::runtime_error("cannot encode PNG: " + png.why());
    std::vector<std::uint8_t> bytes(size);
    if (!png_image_write_to_memory(&png.image, bytes.data(), &size, 0, pixels, 0, nullptr)) {
        throw std::runtime_error("cannot encode PNG: " + png.why());
    }
    bytes.resize(size);
    return bytes;
}

DecodedPng decode_png(std::span<const std::uint8_t> bytes, std::size_t max_pixels) {
    PngImage png;
    if (!png_image_begin_read_from_memory(&png.image, bytes.data(), bytes.size()))
        throw std::runtime_error("not a PNG image: " + png.why());
    const std::size_t width = png.image.width, height = png.image.height;
    if (width == 0 || height == 0 || width > static_cast<std::size_t>(kMaxImageSide) ||
        height > static_cast<std::size_t>(kMaxImageSide) || width * height > max_pixels) {
        throw std::runtime_error("PNG image is " + std::to_string(width) + "x" + std::to_string(height) +
                                 ", more than raster reads");
    }
    png.image.format = PNG_FORMAT_RGBA;
    std::vector<std::uint8_t> rgba(width * height * 4);
    if (!png_image_finish_read(&png.image, nullptr, rgba.data(), 0, nullptr))
        throw std::runtime_error("corrupt PNG image: " + png.why());
    std::vector<std::uint8_t> rgb(width * height * 3), alpha(width * height);
    for (std::size_t i = 0; i < width * height; ++i) {
        std::memcpy(&rgb[i * 3], &rgba[i * 4], 3);
        alpha[i] = rgba[i * 4 + 3];
    }
    return {Framebuffer(static_cast<int>(width), static_cast<int>(height), std::move(rgb)), std::move(alpha)};
}

}  // namespace raster
