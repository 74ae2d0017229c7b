#pragma once

#include <optional>
#include <string_view>

// A part of a clip, frames first..last, as --frame-range names it and webp_parts.hpp marks it.
// Bodies in frame_range.cpp.
namespace raster {

// Frames first..last, both included, of a clip of `total` frames numbered from 0.
struct FrameRange {
    int first = 0;
    int last = 0;
    int total = 0;
    int spacing_ms = 0;  // how long each frame shows: a one-frame part is stored as a still, which has no duration
    [[nodiscard]] int count() const noexcept { return last - first + 1; }
    friend bool operator==(const FrameRange&, const FrameRange&) = default;
};

// Reads "A..B" or "A:B" (decimal, at most nine digits each, 0 <= A <= B) into first and last;
// total and spacing_ms are left 0 for the caller, who knows the clip. nullopt for anything else.
[[nodiscard]] std::optional<FrameRange> frame_range_from_text(std::string_view text);

}  // namespace raster
