#pragma once

#include <cstdint>

// When an animation's frames show: frame i at i * spacing for one spacing each, in the whole
// milliseconds WebP stores. Bodies in frame_timing.cpp.
namespace raster {

// How long each frame lasts at `fps` (1 or more): 1000 / fps rounded to the nearest millisecond.
[[nodiscard]] int frame_spacing_ms(int fps) noexcept;
// How long `count` frames last, `spacing_ms` each.
[[nodiscard]] std::int64_t frames_length_ms(int count, int spacing_ms) noexcept;

}  // namespace raster
