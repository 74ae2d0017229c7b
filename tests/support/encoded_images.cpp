#include "encoded_images.hpp"

// stb_image_write is third-party code written for C: its own warnings are not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wpedantic"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace test_support {

namespace {

void append(void* context, void* data, int size) {
    const auto* begin = static_cast<const std::uint8_t*>(data);
    static_cast<Bytes*>(context)->insert(static_cast<Bytes*>(context)->end(), begin, begin + size);
}

}  // namespace

Bytes encode_png(const Bytes& pixels, int width, int height, int channels) {
    Bytes out;
    stbi_write_png_to_func(append, &out, width, height, channels, pixels.data(), width * channels);
    return out;
}

Bytes encode_jpeg(const Bytes& pixels, int width, int height, int channels) {
    Bytes out;
    stbi_write_jpg_to_func(append, &out, width, height, channels, pixels.data(), 90);
    return out;
}

Bytes encode_bmp(const Bytes& pixels, int width, int height, int channels) {
    Bytes out;
    stbi_write_bmp_to_func(append, &out, width, height, channels, pixels.data());
    return out;
}

Bytes encode_tga(const Bytes& pixels, int width, int height, int channels, bool rle) {
    Bytes out;
    stbi_write_tga_with_rle = rle ? 1 : 0;
    stbi_write_tga_to_func(append, &out, width, height, channels, pixels.data());
    return out;
}

}  // namespace test_support
