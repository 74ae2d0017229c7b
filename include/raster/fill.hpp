#pragma once

#include <raster/framebuffer.hpp>

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>

namespace raster {

// Corner coordinates beyond this many pixels from the origin make fill_quad draw nothing
// (they would overflow the exact 64-bit edge functions).
inline constexpr int kMaxFillCoordinate = 1 << 29;

// Fills a convex quad given by its corners in order (either winding, any starting corner):
// a pixel is painted when its centre lies inside or on every edge (doc/conventions.md#fill).
// A quad of zero area draws nothing. The scan covers the quad's bounding box clamped to the
// buffer; returns the number of pixels tested.
std::int64_t fill_quad(Framebuffer& framebuffer, const std::array<glm::ivec2, 4>& corners,
                       Rgb colour);

}  // namespace raster
