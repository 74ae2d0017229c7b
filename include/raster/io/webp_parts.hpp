#pragma once

#include <raster/io/frame_range.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

// Animations rendered in parts, a range of frames each (on several machines, or restartably),
// and joined back without re-encoding a pixel. Bodies in src/io/webp/parts.cpp, which walks each
// file's chunks once, so that time is linear in frames.
namespace raster {

// The animation marked as frames `range` of a longer clip, in a chunk players ignore ("RNGE").
// Throws std::runtime_error for bytes that are not a WebP animation.
[[nodiscard]] std::vector<std::uint8_t> mark_frame_range(std::span<const std::uint8_t> animation, FrameRange range);
// The range an animation was marked with; nullopt for an unmarked one.
[[nodiscard]] std::optional<FrameRange> frame_range_of(std::span<const std::uint8_t> animation);
// The number of frames an animation holds, without decoding them (1 for a still).
[[nodiscard]] int webp_frame_count(std::span<const std::uint8_t> webp);

struct AnimationPart {
    std::string name;  // for errors: the file it came from
    std::vector<std::uint8_t> bytes;
};

// The whole clip from marked parts given in any order: their frames copied as they are, in
// order, each part's first frame drawn over nothing. The parts must tile 0..total-1 with no
// gap or overlap, share the canvas and the frame spacing; otherwise std::runtime_error says in
// one line which part or which frames are wrong.
[[nodiscard]] std::vector<std::uint8_t> assemble_parts(std::vector<AnimationPart> parts);

}  // namespace raster
