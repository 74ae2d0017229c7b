// Parts of an animation: marked with their frame range, and joined without decoding a pixel.
// Frames are walked chunk by chunk (chunks.hpp), so joining is linear in frames.
#include <raster/io/frame_timing.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/io/webp_parts.hpp>

#include "io/webp/chunks.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <webp/decode.h>
#include <webp/mux.h>

namespace raster {
namespace {

using detail::WebpChunk;

constexpr std::string_view kRangeChunk = "RNGE";

std::uint32_t word_at(std::span<const std::uint8_t> bytes, std::size_t at, std::size_t count = 4) {
    std::uint32_t value = 0;
    for (std::size_t b = 0; b < count; ++b) value |= static_cast<std::uint32_t>(bytes[at + b]) << (8 * b);
    return value;
}

std::vector<WebpChunk> chunks_of(std::span<const std::uint8_t> bytes, const std::string& name) {
    std::optional<std::vector<WebpChunk>> chunks = detail::webp_chunks(bytes);
    if (!chunks) throw std::runtime_error(name + " is not a WebP file");
    return std::move(*chunks);
}

std::optional<FrameRange> range_in(const std::vector<WebpChunk>& chunks) {
    const auto chunk =
        std::find_if(chunks.begin(), chunks.end(), [](const WebpChunk& c) { return c.tag == kRangeChunk; });
    if (chunk == chunks.end() || chunk->payload.size() != 16) return std::nullopt;
    const std::uint32_t first = word_at(chunk->payload, 0), last = word_at(chunk->payload, 4),
                        total = word_at(chunk->payload, 8), spacing = word_at(chunk->payload, 12);
    if (!(first <= last && last < total && total <= static_cast<std::uint32_t>(std::numeric_limits<int>::max())))
        return std::nullopt;
    if (!(spacing >= 1 && spacing <= static_cast<std::uint32_t>(kMaxFrameSpacingMs))) return std::nullopt;
    return FrameRange{static_cast<int>(first), static_cast<int>(last), static_cast<int>(total),
                      static_cast<int>(spacing)};
}

std::size_t frames_in(const std::vector<WebpChunk>& chunks) {
    return static_cast<std::size_t>(
        std::count_if(chunks.begin(), chunks.end(), [](const WebpChunk& c) { return c.tag == "ANMF"; }));
}

std::string frames_text(int first, int last) {
    return first == last ? "frame " + std::to_string(first)
                         : "frames " + std::to_string(first) + ".." + std::to_string(last);
}

std::string in_no_part(int first, int last) {
    return frames_text(first, last) + (first == last ? " is" : " are") + " in no part";
}

std::vector<std::uint8_t> range_chunk(FrameRange range) {
    std::vector<std::uint8_t> chunk{'R', 'N', 'G', 'E', 16, 0, 0, 0};
    for (const int value : {range.first, range.last, range.total, range.spacing_ms}) {
        for (std::size_t b = 0; b < 4; ++b)
            chunk.push_back(static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * b)));
    }
    return chunk;
}

}  // namespace

std::vector<std::uint8_t> mark_frame_range(std::span<const std::uint8_t> animation, FrameRange range) {
    const std::vector<WebpChunk> chunks = chunks_of(animation, "the animation");
    const std::vector<std::uint8_t> marker = range_chunk(range);
    if (!chunks.empty() && chunks.front().tag == "VP8X") {
        // An extended file takes the chunk at its end, after any old mark is dropped.
        std::vector<std::uint8_t> bytes(animation.begin(), animation.begin() + 12);
        for (const WebpChunk& chunk : chunks) {
            if (chunk.tag == kRangeChunk) continue;
            const std::uint8_t* begin = chunk.payload.data() - 8;
            bytes.insert(bytes.end(), begin, chunk.payload.data() + chunk.payload.size());
            if (chunk.payload.size() & 1U) bytes.push_back(0);
        }
        bytes.insert(bytes.end(), marker.begin(), marker.end());
        if (bytes.size() - 8 > 0xFFFFFFFEU)
            throw std::runtime_error("cannot mark the animation's frame range: it would pass WebP's 4 GiB");
        for (std::size_t b = 0; b < 4; ++b) bytes[4 + b] = static_cast<std::uint8_t>((bytes.size() - 8) >> (8 * b));
        return bytes;
    }
    // A simple still needs the extended header first: libwebp's muxer adds it (one picture, no frames to walk).
    const WebPData data{animation.data(), animation.size()};
    const std::unique_ptr<WebPMux, void (*)(WebPMux*)> mux(WebPMuxCreate(&data, 0), WebPMuxDelete);
    const WebPData chunk{marker.data() + 8, 16};
    WebPData out;
    WebPDataInit(&out);
    if (!mux || WebPMuxSetChunk(mux.get(), "RNGE", &chunk, 1) != WEBP_MUX_OK ||
        WebPMuxAssemble(mux.get(), &out) != WEBP_MUX_OK) {
        throw std::runtime_error("cannot mark the animation's frame range");
    }
    std::vector<std::uint8_t> bytes(out.bytes, out.bytes + out.size);
    WebPDataClear(&out);
    return bytes;
}

std::optional<FrameRange> frame_range_of(std::span<const std::uint8_t> animation) {
    const std::optional<std::vector<WebpChunk>> chunks = detail::webp_chunks(animation);
    return chunks ? range_in(*chunks) : std::nullopt;
}

int webp_frame_count(std::span<const std::uint8_t> webp) {
    const std::size_t frames = frames_in(chunks_of(webp, "the file"));
    return frames > 0 ? static_cast<int>(std::min<std::size_t>(frames, std::numeric_limits<int>::max())) : 1;
}

std::vector<std::uint8_t> assemble_parts(std::vector<AnimationPart> parts) {
    if (parts.empty()) throw std::runtime_error("no parts to assemble");
    struct Opened {
        const AnimationPart* part;
        std::vector<WebpChunk> chunks;
        FrameRange range;
        int width = 0;
        int height = 0;
    };
    std::vector<Opened> opened;
    for (const AnimationPart& part : parts) {
        const std::string name = "'" + printable(part.name) + "'";
        std::vector<WebpChunk> chunks = chunks_of(part.bytes, name);
        const std::optional<FrameRange> range = range_in(chunks);
        if (!range)
            throw std::runtime_error(name + " is not a part: it has no frame range (render it with --frame-range)");
        // A marked file is extended: its canvas is in the VP8X chunk that comes first.
        if (chunks.front().tag != "VP8X" || chunks.front().payload.size() < 10)
            throw std::runtime_error(name + " has no canvas");
        const int w = static_cast<int>(word_at(chunks.front().payload, 4, 3)) + 1,
                  h = static_cast<int>(word_at(chunks.front().payload, 7, 3)) + 1;
        opened.push_back({&part, std::move(chunks), *range, w, h});
    }
    std::sort(opened.begin(), opened.end(),
              [](const Opened& a, const Opened& b) { return a.range.first < b.range.first; });
    const Opened& head = opened.front();
    const int width = head.width, height = head.height;
    detail::AnimationAssembler whole(width, height, 0xFF000000U, 0);  // as AnimationEncoder writes: loop forever
    int next = 0;
    const int spacing = head.range.spacing_ms;
    for (const Opened& piece : opened) {
        const std::string name = "'" + printable(piece.part->name) + "'";
        if (piece.width != width || piece.height != height) {
            throw std::runtime_error(name + " is " + std::to_string(piece.width) + "x" + std::to_string(piece.height) +
                                     ", the others " + std::to_string(width) + "x" + std::to_string(height));
        }
        if (piece.range.total != head.range.total) {
            throw std::runtime_error(name + " is part of a clip of " + std::to_string(piece.range.total) +
                                     " frames, '" + printable(head.part->name) + "' of " +
                                     std::to_string(head.range.total));
        }
        if (piece.range.first > next) throw std::runtime_error(in_no_part(next, piece.range.first - 1));
        if (piece.range.first < next)
            throw std::runtime_error(name + " repeats " +
                                     frames_text(piece.range.first, std::min(next - 1, piece.range.last)));
        if (piece.range.spacing_ms != spacing) {
            throw std::runtime_error(name + " shows frames for " + std::to_string(piece.range.spacing_ms) +
                                     " ms, the others for " + std::to_string(spacing));
        }
        // libwebp's own encoder merges a repeated frame into the one before, lengthening it, so
        // a part is checked by how long its frames last, not by how many it stores.
        const std::int64_t expected_ms = frames_length_ms(piece.range.count(), spacing);
        std::int64_t lasts_ms = 0;
        std::vector<detail::AnimationFrame> frames;
        for (const WebpChunk& chunk : piece.chunks) {
            if (chunk.tag != "ANMF") continue;
            const std::int64_t shown = piece.range.first + lasts_ms / spacing;  // the clip's number for this frame
            const std::optional<detail::AnimationFrame> frame = detail::parse_frame(chunk.payload);
            if (!frame)
                throw std::runtime_error(name + " has a corrupt frame " + std::to_string(shown) +
                                         ": its chunk holds no picture");
            frames.push_back(*frame);
            lasts_ms += frame->duration_ms;
        }
        if (frames.empty()) {  // a still: the whole range in one picture
            const std::span<const std::uint8_t> bytes = piece.part->bytes;
            detail::AnimationFrame still;
            still.image = detail::picture_in(bytes.subspan(12));
            if (expected_ms > kMaxFrameSpacingMs) {
                throw std::runtime_error(name + " holds one picture for " + std::to_string(expected_ms) +
                                         " ms, longer than a WebP frame lasts");
            }
            still.duration_ms = static_cast<int>(expected_ms);
            still.width = width, still.height = height;
            frames.push_back(still);
        }
        lasts_ms = 0;
        for (std::size_t k = 0; k < frames.size(); ++k) {
            detail::AnimationFrame frame = frames[k];
            const std::string corrupt =
                name + " has a corrupt frame " + std::to_string(piece.range.first + lasts_ms / spacing) + ": ";
            // Every picture's header is checked, so that a damaged frame is refused here rather than copied into a clip
            // that does not play.
            WebPBitstreamFeatures features;
            if (frame.image.empty() ||
                WebPGetFeatures(frame.image.data(), frame.image.size(), &features) != VP8_STATUS_OK ||
                features.has_animation != 0) {
                throw std::runtime_error(corrupt + "its picture does not decode");
            }
            if (features.width != frame.width || features.height != frame.height) {
                throw std::runtime_error(corrupt + "its picture is " + std::to_string(features.width) + "x" +
                                         std::to_string(features.height) + ", its rectangle " +
                                         std::to_string(frame.width) + "x" + std::to_string(frame.height));
            }
            if (frame.x + frame.width > width || frame.y + frame.height > height) {
                throw std::runtime_error(corrupt + "its rectangle leaves the " + std::to_string(width) + "x" +
                                         std::to_string(height) + " canvas");
            }
            if (frame.duration_ms <= 0 || frame.duration_ms % spacing != 0) {
                throw std::runtime_error(name + " has a frame lasting " + std::to_string(frame.duration_ms) +
                                         " ms, not a multiple of " + std::to_string(spacing));
            }
            lasts_ms += frame.duration_ms;
            if (k == 0) {
                // A part's first frame must cover the canvas, since it will follow another part's last.
                if (frame.x != 0 || frame.y != 0 || frame.width != width || frame.height != height) {
                    throw std::runtime_error(name + " does not begin with a whole frame");
                }
                frame.blend = false;
            }
            whole.add_frame(frame, features.has_alpha != 0);
        }
        if (lasts_ms != expected_ms) {
            throw std::runtime_error(name + " lasts " + std::to_string(lasts_ms) + " ms, but its range " +
                                     frames_text(piece.range.first, piece.range.last) + " lasts " +
                                     std::to_string(expected_ms));
        }
        next = piece.range.last + 1;
    }
    if (next != head.range.total) throw std::runtime_error(in_no_part(next, head.range.total - 1));
    return std::move(whole).finish();
}

}  // namespace raster
