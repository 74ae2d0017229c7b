#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

// A WebP file's RIFF chunks and animation frames, walked and written in one pass: libwebp's mux
// and demux find each frame by walking from the first, which is quadratic in frames.
namespace raster::detail {

struct WebpChunk {
    std::string_view tag;  // four characters, e.g. "ANMF"
    std::span<const std::uint8_t> payload;
};

// The chunks after "RIFF size WEBP", in order; nullopt for bytes that are not such a file, or
// whose RIFF size or a chunk's size runs past their end.
[[nodiscard]] std::optional<std::vector<WebpChunk>> webp_chunks(std::span<const std::uint8_t> file);

// One frame of an animation, as an ANMF chunk holds it.
struct AnimationFrame {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    int duration_ms = 0;
    bool dispose_to_background = false;
    bool blend = true;                    // drawn over what is there; false: replaces the rectangle
    std::span<const std::uint8_t> image;  // an ALPH chunk and a VP8 one, or a VP8L one: what WebPDecode takes
};

// The frame in an ANMF chunk's payload; nullopt when it is cut short or holds no picture.
[[nodiscard]] std::optional<AnimationFrame> parse_frame(std::span<const std::uint8_t> anmf_payload);

// The picture chunks among `chunks` (an ALPH and a VP8, or a VP8L), as one span of the file.
[[nodiscard]] std::span<const std::uint8_t> picture_in(std::span<const std::uint8_t> chunks);

// Writes an animation's chunks in one pass; the header, which needs the total size and whether
// any frame has alpha, is filled in by finish().
class AnimationAssembler {
public:
    AnimationAssembler(int canvas_width, int canvas_height, std::uint32_t background_argb, int loop_count);
    void add_frame(const AnimationFrame& frame, bool has_alpha);
    // The finished file; throws std::runtime_error when it would pass RIFF's 4 GiB.
    [[nodiscard]] std::vector<std::uint8_t> finish() &&;
    [[nodiscard]] int frames() const noexcept { return frames_; }

private:
    std::vector<std::uint8_t> bytes_;
    bool alpha_ = false;
    int frames_ = 0;
};

}  // namespace raster::detail
