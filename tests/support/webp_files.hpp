#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <string>
#include <vector>

// WebP animations written byte by byte, for inputs libwebp's muxer would refuse to write:
// huge canvases, durations at the limit, damaged frames.
namespace test_support {

struct HandFrame {
    int x = 0;
    int y = 0;
    int width = 1;
    int height = 1;
    int duration_ms = 20;
    std::uint8_t flags = 2;             // ANMF flags: 1 dispose to background, 2 do not blend
    std::vector<std::uint8_t> picture;  // the frame's VP8L chunk, header included
};

// The VP8L chunk of a lossless still of `image`, with `alpha` (a byte a pixel) when not empty.
std::vector<std::uint8_t> vp8l_chunk(const raster::Framebuffer& image, const std::vector<std::uint8_t>& alpha = {});
// The same for `width` x `height` pixels of one colour.
std::vector<std::uint8_t> vp8l_chunk(int width, int height);

// A RIFF chunk: tag, little-endian size, payload, pad byte.
std::vector<std::uint8_t> riff_chunk(const std::string& tag, const std::vector<std::uint8_t>& payload);

// An animated WebP file: VP8X with the canvas, ANIM, the frames, then `extra` chunks as given.
std::vector<std::uint8_t> animated_webp(int canvas_width, int canvas_height, const std::vector<HandFrame>& frames,
                                        const std::vector<std::uint8_t>& extra = {});

// The offset of the n-th (from 0) occurrence of `tag` in `bytes`, or bytes.size().
std::size_t find_tag(const std::vector<std::uint8_t>& bytes, const std::string& tag, int n);

}  // namespace test_support
