#include "io/webp/chunks.hpp"

#include <algorithm>
#include <stdexcept>

namespace raster::detail {
namespace {

std::uint32_t le(std::span<const std::uint8_t> bytes, std::size_t at, std::size_t count) {
    std::uint32_t value = 0;
    for (std::size_t k = 0; k < count; ++k) value |= static_cast<std::uint32_t>(bytes[at + k]) << (8 * k);
    return value;
}

void put_le(std::vector<std::uint8_t>& out, std::uint32_t value, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) out.push_back(static_cast<std::uint8_t>(value >> (8 * k)));
}

void put_le_at(std::vector<std::uint8_t>& out, std::size_t at, std::uint32_t value, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) out[at + k] = static_cast<std::uint8_t>(value >> (8 * k));
}

std::string_view tag_at(std::span<const std::uint8_t> bytes, std::size_t at) {
    return {reinterpret_cast<const char*>(bytes.data() + at), 4};
}

// The chunks of a region; a missing pad byte after the last is forgiven, as libwebp does.
std::optional<std::vector<WebpChunk>> chunks_of(std::span<const std::uint8_t> region) {
    std::vector<WebpChunk> chunks;
    std::size_t at = 0;
    while (at < region.size()) {
        if (region.size() - at < 8) return std::nullopt;
        const std::size_t size = le(region, at + 4, 4);
        if (size > region.size() - at - 8) return std::nullopt;
        chunks.push_back({tag_at(region, at), region.subspan(at + 8, size)});
        at += 8 + size + (size & 1);
    }
    return chunks;
}

}  // namespace

std::optional<std::vector<WebpChunk>> webp_chunks(std::span<const std::uint8_t> file) {
    if (file.size() < 12 || tag_at(file, 0) != "RIFF" || tag_at(file, 8) != "WEBP") return std::nullopt;
    const std::size_t riff_size = le(file, 4, 4);
    if (riff_size < 4 || riff_size > file.size() - 8) return std::nullopt;
    return chunks_of(file.subspan(12, riff_size - 4));
}

std::span<const std::uint8_t> picture_in(std::span<const std::uint8_t> chunks) {
    std::size_t at = 0;
    std::optional<std::size_t> alpha_at;
    while (chunks.size() - at >= 8) {
        const std::string_view tag = tag_at(chunks, at);
        const std::size_t size = le(chunks, at + 4, 4);
        if (size > chunks.size() - at - 8) return {};
        const std::size_t end = std::min(chunks.size(), at + 8 + size + (size & 1));
        if (tag == "VP8L") return chunks.subspan(at, end - at);  // a lossless picture carries its own alpha
        if (tag == "VP8 ") {
            const std::size_t begin = alpha_at.value_or(at);
            return chunks.subspan(begin, end - begin);
        }
        // An ALPH chunk belongs to the VP8 chunk right after it.
        alpha_at = tag == "ALPH" ? std::optional<std::size_t>(at) : std::nullopt;
        at = end;
    }
    return {};
}

std::optional<AnimationFrame> parse_frame(std::span<const std::uint8_t> anmf_payload) {
    if (anmf_payload.size() < 16) return std::nullopt;
    AnimationFrame frame;
    frame.x = static_cast<int>(le(anmf_payload, 0, 3)) * 2;
    frame.y = static_cast<int>(le(anmf_payload, 3, 3)) * 2;
    frame.width = static_cast<int>(le(anmf_payload, 6, 3)) + 1;
    frame.height = static_cast<int>(le(anmf_payload, 9, 3)) + 1;
    frame.duration_ms = static_cast<int>(le(anmf_payload, 12, 3));
    const std::uint8_t flags = anmf_payload[15];
    frame.dispose_to_background = (flags & 1U) != 0;
    frame.blend = (flags & 2U) == 0;
    frame.image = picture_in(anmf_payload.subspan(16));
    if (frame.image.empty()) return std::nullopt;
    return frame;
}

AnimationAssembler::AnimationAssembler(int canvas_width, int canvas_height, std::uint32_t background_argb,
                                       int loop_count) {
    constexpr std::string_view head("RIFF\0\0\0\0WEBPVP8X", 16);
    bytes_.assign(head.begin(), head.end());
    put_le(bytes_, 10, 4);
    put_le(bytes_, 0, 4);  // flags, filled in by finish()
    put_le(bytes_, static_cast<std::uint32_t>(canvas_width - 1), 3);
    put_le(bytes_, static_cast<std::uint32_t>(canvas_height - 1), 3);
    for (const char c : std::string_view("ANIM")) bytes_.push_back(static_cast<std::uint8_t>(c));
    put_le(bytes_, 6, 4);
    put_le(bytes_, background_argb, 4);
    put_le(bytes_, static_cast<std::uint32_t>(loop_count), 2);
}

void AnimationAssembler::add_frame(const AnimationFrame& frame, bool has_alpha) {
    const std::size_t payload = 16 + frame.image.size();
    if (payload > 0xFFFFFFF0U) throw std::runtime_error("a frame is too large for WebP");
    for (const char c : std::string_view("ANMF")) bytes_.push_back(static_cast<std::uint8_t>(c));
    put_le(bytes_, static_cast<std::uint32_t>(payload), 4);
    put_le(bytes_, static_cast<std::uint32_t>(frame.x / 2), 3);
    put_le(bytes_, static_cast<std::uint32_t>(frame.y / 2), 3);
    put_le(bytes_, static_cast<std::uint32_t>(frame.width - 1), 3);
    put_le(bytes_, static_cast<std::uint32_t>(frame.height - 1), 3);
    put_le(bytes_, static_cast<std::uint32_t>(frame.duration_ms), 3);
    bytes_.push_back(static_cast<std::uint8_t>((frame.dispose_to_background ? 1U : 0U) | (frame.blend ? 0U : 2U)));
    bytes_.insert(bytes_.end(), frame.image.begin(), frame.image.end());
    if (payload & 1U) bytes_.push_back(0);
    alpha_ = alpha_ || has_alpha;
    ++frames_;
}

std::vector<std::uint8_t> AnimationAssembler::finish() && {
    // RIFF sizes are 32 bits and count from after the size field.
    if (bytes_.size() - 8 > 0xFFFFFFFEU) throw std::runtime_error("the animation would pass WebP's 4 GiB");
    put_le_at(bytes_, 4, static_cast<std::uint32_t>(bytes_.size() - 8), 4);
    constexpr std::uint8_t kAnimationFlag = 0x02, kAlphaFlag = 0x10;
    bytes_[20] = static_cast<std::uint8_t>(kAnimationFlag | (alpha_ ? kAlphaFlag : 0));
    return std::move(bytes_);
}

}  // namespace raster::detail
