#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <glm/vec2.hpp>

namespace raster {

// Draws the segment between two pixels with a DDA: N = max(|dx|, |dy|) equal steps, N + 1
// samples, each rounded to the nearest pixel, both endpoints included (doc/conventions.md#lines).
// Only the samples that land inside the buffer are walked, so a segment's cost follows its
// visible part, not its length. The framebuffer's top-left pixel sits at `origin`.
// Returns the number of samples walked.
std::int64_t draw_line(Framebuffer& framebuffer, glm::ivec2 from, glm::ivec2 to, Rgb colour,
                       glm::ivec2 origin = {0, 0});

}  // namespace raster
