#pragma once

#include <cstdint>
#include <vector>

// Image files of every format raster reads, encoded by stb_image_write (the one test file that
// includes it) so that the readers meet files another encoder wrote.
namespace test_support {

using Bytes = std::vector<std::uint8_t>;

// `pixels` holds `channels` bytes per pixel, rows top to bottom.
Bytes encode_png(const Bytes& pixels, int width, int height, int channels);
Bytes encode_jpeg(const Bytes& pixels, int width, int height, int channels);
Bytes encode_bmp(const Bytes& pixels, int width, int height, int channels);
Bytes encode_tga(const Bytes& pixels, int width, int height, int channels, bool rle);

}  // namespace test_support
