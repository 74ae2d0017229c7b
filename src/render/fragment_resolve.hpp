#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/depth_buffer.hpp>

#include "rasterize/fragment_list.hpp"
#include "rasterize/sample_buffer.hpp"

#include <cstdint>

// A strip's transparent fragments composited over its opaque result once every object is drawn
// (doc/conventions.md#transparency).
namespace raster::detail {

// Where the opaque result of the frame lies: the resolved framebuffer, with the samples it was
// resolved from when multisampling, else the depth buffer (nullptr: a scene without one).
struct OpaqueResult {
    Framebuffer* frame;
    SampleBuffer* samples = nullptr;
    DepthBuffer* depth = nullptr;
};

// Sorts `list` (of rows [y_begin, y_end)) by pixel and, within a pixel, from far to near (equal depths in drawing
// order), then writes each pixel it reaches: every sample's opaque colour with the fragments covering it composited
// over it in linear light, premultiplied, and the samples' mean. With `alpha` (one byte a pixel), the opaque surfaces
// count as alpha 1 and the background as 0: the pixel's alpha is the samples' mean of 1 - (1 - coverage) x the product
// of (1 - alpha), its colour the surfaces' alone. At one sample, the alpha of every pixel of rows [y_begin, y_end) is
// written first from the depth buffer's coverage.
void resolve_fragments(FragmentList& list, OpaqueResult opaque, std::uint8_t* alpha, int y_begin, int y_end);

}  // namespace raster::detail
