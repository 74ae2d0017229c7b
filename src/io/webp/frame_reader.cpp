// Animations decoded frame by frame onto one canvas, composited as libwebp's WebPAnimDecoder
// does (anim_decode.c), which holds the canvas three times over.
#include <raster/io/webp.hpp>

#include "io/webp/chunks.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <webp/decode.h>
#include <webp/demux.h>

namespace raster {
namespace {

std::vector<std::uint8_t> read_webp_file(const std::filesystem::path& path, std::vector<InputRecord>* sources) {
    InputRules rules;
    rules.role = "animation";
    rules.max_bytes = kMaxWebpFileBytes;
    rules.signature = looks_like_webp;
    rules.signature_bytes = 12;
    rules.expected = "a WebP file";
    try {
        return read_input_file(path, rules, sources);
    } catch (const std::runtime_error& problem) {
        throw std::runtime_error("'" + printable(path.string()) + "' " + problem.what());
    }
}

bool covers(const detail::AnimationFrame& frame, const WebpInfo& canvas) {
    return frame.width == canvas.width && frame.height == canvas.height;
}

bool inside(const detail::AnimationFrame& frame, int x, int y) {
    return x >= frame.x && x < frame.x + frame.width && y >= frame.y && y < frame.y + frame.height;
}

}  // namespace

struct WebpFrameReader::State {
    std::string name;  // quoted, for errors
    std::vector<std::uint8_t> bytes;
    WebpInfo info{};
    std::vector<detail::AnimationFrame> frames;  // pictures are spans of `bytes`
    std::size_t next = 0;
    std::optional<DecodedFrame> canvas;
    std::vector<std::uint8_t> rgba;  // the frame being decoded
    detail::AnimationFrame previous;
    bool previous_was_key = false;
    std::int64_t elapsed_ms = 0;

    void clear(const detail::AnimationFrame& area) {
        for (int y = area.y; y < area.y + area.height; ++y) {
            const std::size_t at =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(info.width) + static_cast<std::size_t>(area.x);
            std::fill_n(canvas->image.pixels() + at * 3, static_cast<std::size_t>(area.width) * 3, std::uint8_t{0});
            std::fill_n(canvas->alpha.begin() + static_cast<std::ptrdiff_t>(at), area.width, std::uint8_t{0});
        }
    }

    [[noreturn]] void corrupt(const std::string& why) const {
        throw std::runtime_error(name + " has a corrupt frame " + std::to_string(next) + ": " + why);
    }

    // Decodes the frame into `rgba` at its own size, so that memory is one canvas and one frame.
    void decode(const detail::AnimationFrame& frame) {
        rgba.resize(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height) * 4);
        WebPDecoderConfig config;
        if (!WebPInitDecoderConfig(&config)) throw std::runtime_error("libwebp version mismatch");
        config.output.colorspace = MODE_RGBA;
        config.output.is_external_memory = 1;
        config.output.u.RGBA.rgba = rgba.data();
        config.output.u.RGBA.stride = frame.width * 4;
        config.output.u.RGBA.size = rgba.size();
        config.options.use_threads = 0;
        const VP8StatusCode status = WebPDecode(frame.image.data(), frame.image.size(), &config);
        WebPFreeDecBuffer(&config.output);
        if (status != VP8_STATUS_OK)
            corrupt("its picture does not decode (libwebp status " + std::to_string(status) + ")");
    }
};

namespace {

// libwebp's BlendPixelNonPremult: `src` over the canvas pixel, neither premultiplied, in its
// integer arithmetic, so that pixels match its decoder's exactly.
void blend_over(const std::uint8_t* src, std::uint8_t* rgb, std::uint8_t& alpha) {
    const std::uint32_t src_a = src[3];
    if (src_a == 0) return;
    const std::uint32_t dst_factor_a = (alpha * (256U - src_a)) >> 8;
    const std::uint32_t blend_a = src_a + dst_factor_a;
    const std::uint32_t scale = (1U << 24) / blend_a;
    for (int c = 0; c < 3; ++c) {
        const std::uint32_t unscaled = src[c] * src_a + rgb[c] * dst_factor_a;
        rgb[c] = static_cast<std::uint8_t>((unscaled * scale) >> 24);
    }
    alpha = static_cast<std::uint8_t>(blend_a);
}

}  // namespace

WebpFrameReader::WebpFrameReader(const std::filesystem::path& path, std::vector<InputRecord>* sources)
    : state_(std::make_unique<State>()) {
    State& s = *state_;
    s.name = "'" + printable(path.string()) + "'";
    s.bytes = read_webp_file(path, sources);
    // libwebp's demuxer checks the container (frames inside the canvas, chunk sizes); its frame
    // lookups walk from the first, so the frames themselves are walked here.
    const WebPData data{s.bytes.data(), s.bytes.size()};
    const std::unique_ptr<WebPDemuxer, void (*)(WebPDemuxer*)> demux(WebPDemux(&data), WebPDemuxDelete);
    if (!demux) throw std::runtime_error(s.name + " is not a WebP file raster can decode");
    s.info = {static_cast<int>(WebPDemuxGetI(demux.get(), WEBP_FF_CANVAS_WIDTH)),
              static_cast<int>(WebPDemuxGetI(demux.get(), WEBP_FF_CANVAS_HEIGHT)),
              static_cast<int>(WebPDemuxGetI(demux.get(), WEBP_FF_FRAME_COUNT))};
    if ((WebPDemuxGetI(demux.get(), WEBP_FF_FORMAT_FLAGS) & ANIMATION_FLAG) != 0) {
        const std::optional<std::vector<detail::WebpChunk>> chunks = detail::webp_chunks(s.bytes);
        for (const detail::WebpChunk& chunk : chunks.value_or(std::vector<detail::WebpChunk>{})) {
            if (chunk.tag != "ANMF") continue;
            const std::optional<detail::AnimationFrame> frame = detail::parse_frame(chunk.payload);
            if (!frame) break;
            s.frames.push_back(*frame);
        }
    } else {
        WebPIterator still;
        if (WebPDemuxGetFrame(demux.get(), 1, &still)) {
            s.frames.push_back({still.x_offset,
                                still.y_offset,
                                still.width,
                                still.height,
                                still.duration,
                                still.dispose_method == WEBP_MUX_DISPOSE_BACKGROUND,
                                still.blend_method == WEBP_MUX_BLEND,
                                {still.fragment.bytes, still.fragment.size}});
            WebPDemuxReleaseIterator(&still);
        }
    }
    if (s.info.width < 1 || s.info.height < 1 || s.info.width > kMaxImageSide || s.info.height > kMaxImageSide ||
        s.frames.size() != static_cast<std::size_t>(s.info.frame_count)) {
        throw std::runtime_error(s.name + " is not a WebP file raster can decode");
    }
}

WebpFrameReader::~WebpFrameReader() = default;
WebpFrameReader::WebpFrameReader(WebpFrameReader&&) noexcept = default;
WebpFrameReader& WebpFrameReader::operator=(WebpFrameReader&&) noexcept = default;

const WebpInfo& WebpFrameReader::info() const noexcept { return state_->info; }

const DecodedFrame* WebpFrameReader::next() {
    State& s = *state_;
    if (s.next >= s.frames.size()) return nullptr;
    const detail::AnimationFrame& frame = s.frames[s.next];
    WebPBitstreamFeatures features;
    if (WebPGetFeatures(frame.image.data(), frame.image.size(), &features) != VP8_STATUS_OK ||
        features.has_animation != 0) {
        s.corrupt("its picture's header does not decode");
    }
    if (features.width != frame.width || features.height != frame.height || frame.x + frame.width > s.info.width ||
        frame.y + frame.height > s.info.height) {
        s.corrupt("its picture does not fit its rectangle on the canvas");
    }
    if (!s.canvas) {
        const auto pixels = static_cast<std::size_t>(s.info.width) * static_cast<std::size_t>(s.info.height);
        s.canvas.emplace(
            DecodedFrame{Framebuffer(s.info.width, s.info.height), 0, 0, std::vector<std::uint8_t>(pixels, 0)});
    }
    if (s.next > 0 && s.previous.dispose_to_background) s.clear(s.previous);
    // A key frame starts from a transparent canvas: WebPAnimDecoder's IsKeyFrame.
    const bool key = s.next == 0 || ((features.has_alpha == 0 || !frame.blend) && covers(frame, s.info)) ||
                     (s.previous.dispose_to_background && (covers(s.previous, s.info) || s.previous_was_key));
    if (key) s.clear({0, 0, s.info.width, s.info.height, 0, false, false, {}});
    s.decode(frame);
    // Blending shows the canvas through transparent pixels, except where the previous frame was
    // just disposed of: there libwebp keeps the decoded pixel as it is.
    const bool blending = s.next > 0 && frame.blend && !key;
    const std::uint8_t* src = s.rgba.data();
    std::uint8_t* rgb = s.canvas->image.pixels();
    for (int y = frame.y; y < frame.y + frame.height; ++y) {
        for (int x = frame.x; x < frame.x + frame.width; ++x, src += 4) {
            const std::size_t at =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(s.info.width) + static_cast<std::size_t>(x);
            std::uint8_t& alpha = s.canvas->alpha[at];
            if (blending && src[3] != 255 && !(s.previous.dispose_to_background && inside(s.previous, x, y))) {
                blend_over(src, rgb + at * 3, alpha);
            } else {
                std::copy(src, src + 3, rgb + at * 3);
                alpha = src[3];
            }
        }
    }
    s.canvas->start_ms = s.elapsed_ms;
    s.canvas->duration_ms = frame.duration_ms;
    s.elapsed_ms += frame.duration_ms;
    s.previous = frame;
    s.previous_was_key = key;
    ++s.next;
    return &*s.canvas;
}

WebpInfo for_each_webp_frame(const std::filesystem::path& path, const std::function<bool(const DecodedFrame&)>& visit,
                             std::vector<InputRecord>* sources) {
    WebpFrameReader reader(path, sources);
    while (const DecodedFrame* frame = reader.next()) {
        if (!visit(*frame)) break;
    }
    return reader.info();
}

DecodedWebp read_webp(const std::filesystem::path& path) {
    DecodedWebp result{0, 0, {}};
    const WebpInfo info = for_each_webp_frame(path, [&](const DecodedFrame& frame) {
        result.frames.push_back(frame);
        return true;
    });
    result.width = info.width;
    result.height = info.height;
    return result;
}

}  // namespace raster
