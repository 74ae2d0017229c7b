#pragma once

#include <cstdint>
#include <vector>
#include <webp/encode.h>

// One picture's lossless bytes: a whole still, or the rectangle of an animation frame that changed.
namespace raster::detail {

// `channels` is 3 for RGB, 4 for RGBA whose transparent pixels show the frame below; throws
// std::runtime_error when libwebp cannot import or encode it.
[[nodiscard]] std::vector<std::uint8_t> encode_lossless(const std::uint8_t* rgb, int width, int height, int stride,
                                                        const WebPConfig& config, int channels = 3);

}  // namespace raster::detail
