#pragma once

#include <raster/image/framebuffer.hpp>

// What the parallel animation path encodes of each frame: only the rectangle that changed.
namespace raster::detail {

// A rectangle of a frame, in pixels.
struct Region {
    int x = 0, y = 0, width = 1, height = 1;
};

// The smallest rectangle holding every pixel that differs between two frames of one size, its
// corner moved up and left to even coordinates (WebP stores frame offsets halved); one pixel at
// the origin when nothing changed, so that every frame keeps its place in the file.
[[nodiscard]] Region changed_region(const Framebuffer& before, const Framebuffer& after);

}  // namespace raster::detail
