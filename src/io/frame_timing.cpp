#include <raster/io/frame_timing.hpp>

namespace raster {

int frame_spacing_ms(int fps) noexcept { return (1000 + fps / 2) / fps; }

std::int64_t frames_length_ms(int count, int spacing_ms) noexcept { return std::int64_t{count} * spacing_ms; }

}  // namespace raster
