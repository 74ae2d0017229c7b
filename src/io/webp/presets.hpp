#pragma once

#include <raster/io/webp.hpp>

#include <webp/encode.h>

// Each Effort as libwebp's lossless settings, in one place for stills, animations and the
// parallel path's frames (doc/performance.md has the measured trade-offs).
namespace raster::detail {

// The still's and libwebp animation encoder's settings: exact, lossless, the effort's method and quality.
[[nodiscard]] WebPConfig lossless_config(Effort effort);
// Each frame's own settings on the parallel path.
[[nodiscard]] WebPConfig parallel_config(Effort effort);
// Whether libwebp's animation encoder searches for the smallest file.
[[nodiscard]] bool minimize_size(Effort effort);

}  // namespace raster::detail
