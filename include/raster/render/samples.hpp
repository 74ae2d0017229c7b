#pragma once

#include <span>
#include <glm/vec2.hpp>

// Anti-aliasing by samples: a frame drawn once per sample position, each pass's pixel centres
// moved to that position, and the passes averaged in linear light (doc/conventions.md#samples).
namespace raster {

// The sample counts there are positions for.
inline constexpr int kSampleCounts[] = {1, 2, 4, 8, 16};
// The samples `render` and the seed scenes draw by default: the fewest whose worst pixel on any
// edge of the anti-aliasing lab's corpus is off by less than half the contrast, where a stair-step
// stops showing (doc/lab/README.md#anti-aliasing). The diary's scenes keep 1, its own pictures.
inline constexpr int kSmoothSamples = 4;

// The standard sample positions of Direct3D 11 and Vulkan for `samples` per pixel, in pixels
// from the pixel centre (x right, y down; multiples of 1/16, so they sit on the subpixel grid).
// Throws std::invalid_argument for a count other than 1, 2, 4, 8 or 16.
[[nodiscard]] std::span<const glm::vec2> sample_offsets(int samples);

}  // namespace raster
