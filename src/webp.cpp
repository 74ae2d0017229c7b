// The only file that includes libwebp.
#include <raster/webp.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <webp/decode.h>
#include <webp/demux.h>
#include <webp/encode.h>
#include <webp/mux.h>

namespace raster {
namespace {

struct EncoderSettings {
    int method;
    float quality;
    bool minimize_size;
};

EncoderSettings settings_for(Effort effort) {
    switch (effort) {
    case Effort::fast: return {0, 0.0F, true};
    case Effort::balanced: return {4, 50.0F, true};
    case Effort::max: return {6, 100.0F, true};
    }
    throw std::invalid_argument("unknown effort");
}

WebPConfig lossless_config(Effort effort) {
    WebPConfig config;
    if (!WebPConfigInit(&config)) throw std::runtime_error("libwebp version mismatch");
    const EncoderSettings settings = settings_for(effort);
    config.lossless = 1;
    config.exact = 1;
    config.method = settings.method;
    config.quality = settings.quality;
    return config;
}

// A WebPPicture holding a copy of the frame's pixels, freed on scope exit.
struct Picture {
    WebPPicture picture;

    explicit Picture(const Framebuffer& image) {
        if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp version mismatch");
        picture.use_argb = 1;
        picture.width = image.width();
        picture.height = image.height();
        if (!WebPPictureImportRGB(&picture, image.bytes().data(), image.width() * 3)) {
            throw std::runtime_error("out of memory importing a frame");
        }
    }
    ~Picture() { WebPPictureFree(&picture); }
    Picture(const Picture&) = delete;
    Picture& operator=(const Picture&) = delete;
};

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read '" + path.string() + "'");
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Drops the alpha channel of an RGBA buffer that libwebp decoded.
Framebuffer framebuffer_from_rgba(const std::uint8_t* rgba, int width, int height) {
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<std::uint8_t> rgb(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        rgb[i * 3] = rgba[i * 4];
        rgb[i * 3 + 1] = rgba[i * 4 + 1];
        rgb[i * 3 + 2] = rgba[i * 4 + 2];
    }
    return {width, height, std::move(rgb)};
}

}  // namespace

std::vector<std::uint8_t> encode_webp_still(const Framebuffer& image, Effort effort) {
    const WebPConfig config = lossless_config(effort);
    Picture frame(image);
    WebPMemoryWriter memory;
    WebPMemoryWriterInit(&memory);
    frame.picture.writer = WebPMemoryWrite;
    frame.picture.custom_ptr = &memory;
    const bool encoded = WebPEncode(&config, &frame.picture) != 0;
    std::vector<std::uint8_t> bytes(memory.mem, memory.mem + memory.size);
    WebPMemoryWriterClear(&memory);
    if (!encoded) throw std::runtime_error("cannot encode a still: libwebp error " + std::to_string(frame.picture.error_code));
    return bytes;
}

std::uintmax_t write_webp_still(const Framebuffer& image, const std::filesystem::path& path,
                                Effort effort, OutputPolicy policy) {
    check_output_path(path, policy);
    const std::vector<std::uint8_t> bytes = encode_webp_still(image, effort);
    write_output_file(path, bytes, policy);
    return bytes.size();
}

struct AnimationEncoder::State {
    int width;
    int height;
    int frame_spacing_ms;
    std::int64_t next_timestamp_ms = 0;
    WebPConfig config;
    WebPAnimEncoder* encoder = nullptr;

    State(int w, int h, int spacing, Effort effort)
        : width(w), height(h), frame_spacing_ms(spacing), config(lossless_config(effort)) {
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
            throw std::invalid_argument("animation size must be 1.." + std::to_string(kMaxImageSide) +
                                        " on each side, got " + std::to_string(w) + "x" + std::to_string(h));
        }
        if (spacing < 1 || spacing > kMaxFrameSpacingMs) {
            throw std::invalid_argument("frame spacing must be 1.." + std::to_string(kMaxFrameSpacingMs) +
                                        " ms, got " + std::to_string(spacing));
        }
        WebPAnimEncoderOptions options;
        if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("libwebp version mismatch");
        options.minimize_size = settings_for(effort).minimize_size ? 1 : 0;
        options.allow_mixed = 0;
        options.anim_params.loop_count = 0;
        options.anim_params.bgcolor = 0xFF000000U;  // opaque black, ARGB
        encoder = WebPAnimEncoderNew(width, height, &options);
        if (encoder == nullptr) throw std::runtime_error("cannot start the WebP animation encoder");
    }
    ~State() { WebPAnimEncoderDelete(encoder); }
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    // The timestamp after the next frame, checked before libwebp's int can overflow.
    int end_of_next_frame() const {
        const std::int64_t end = next_timestamp_ms + frame_spacing_ms;
        if (end > std::numeric_limits<int>::max()) {
            throw std::length_error("the animation would last longer than WebP's 2147483647 ms");
        }
        return static_cast<int>(end);
    }

    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("cannot encode the animation: " + what + ": " + WebPAnimEncoderGetError(encoder));
    }
};

AnimationEncoder::AnimationEncoder(int width, int height, int frame_spacing_ms, Effort effort)
    : state_(std::make_unique<State>(width, height, frame_spacing_ms, effort)) {}

AnimationEncoder::~AnimationEncoder() = default;
AnimationEncoder::AnimationEncoder(AnimationEncoder&&) noexcept = default;
AnimationEncoder& AnimationEncoder::operator=(AnimationEncoder&&) noexcept = default;

void AnimationEncoder::add_frame(const Framebuffer& frame) {
    if (!state_) throw std::logic_error("AnimationEncoder used after finish()");
    if (frame.width() != state_->width || frame.height() != state_->height) {
        throw std::invalid_argument("frame size differs from the animation's");
    }
    const int end_ms = state_->end_of_next_frame();  // the last frame needs its end stamp too
    const auto start_ms = static_cast<int>(state_->next_timestamp_ms);
    Picture picture(frame);
    if (!WebPAnimEncoderAdd(state_->encoder, &picture.picture, start_ms, &state_->config)) {
        state_->fail("frame at " + std::to_string(start_ms) + " ms");
    }
    state_->next_timestamp_ms = end_ms;
}

std::vector<std::uint8_t> AnimationEncoder::finish() {
    if (!state_) throw std::logic_error("AnimationEncoder::finish() called twice");
    const std::unique_ptr<State> state = std::move(state_);
    // A last empty add sets the final frame's duration to one full spacing.
    if (!WebPAnimEncoderAdd(state->encoder, nullptr, static_cast<int>(state->next_timestamp_ms), nullptr)) {
        state->fail("end of animation");
    }
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAssemble(state->encoder, &data)) state->fail("assembling");
    std::vector<std::uint8_t> bytes(data.bytes, data.bytes + data.size);
    WebPDataClear(&data);
    return bytes;
}

AnimationWriter::AnimationWriter(const std::filesystem::path& path, int width, int height,
                                 int frame_spacing_ms, Effort effort, OutputPolicy policy)
    : path_(path), policy_(policy), encoder_(width, height, frame_spacing_ms, effort) {
    check_output_path(path_, policy_);
}

std::uintmax_t AnimationWriter::finish() {
    const std::vector<std::uint8_t> bytes = encoder_.finish();
    write_output_file(path_, bytes, policy_);
    return bytes.size();
}

WebpInfo for_each_webp_frame(const std::filesystem::path& path,
                             const std::function<bool(const DecodedFrame&)>& visit) {
    const std::vector<std::uint8_t> bytes = read_bytes(path);
    const WebPData data{bytes.data(), bytes.size()};
    WebPAnimDecoderOptions options;
    if (!WebPAnimDecoderOptionsInit(&options)) throw std::runtime_error("libwebp version mismatch");
    options.color_mode = MODE_RGBA;
    options.use_threads = 0;
    const std::unique_ptr<WebPAnimDecoder, void (*)(WebPAnimDecoder*)> decoder(
        WebPAnimDecoderNew(&data, &options), WebPAnimDecoderDelete);
    WebPAnimInfo info;
    if (!decoder || !WebPAnimDecoderGetInfo(decoder.get(), &info)) {
        throw std::runtime_error("'" + path.string() + "' is not a WebP file");
    }
    const WebpInfo result{static_cast<int>(info.canvas_width), static_cast<int>(info.canvas_height),
                          static_cast<int>(info.frame_count)};
    int previous_end_ms = 0;
    while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
        std::uint8_t* rgba = nullptr;
        int end_ms = 0;
        if (!WebPAnimDecoderGetNext(decoder.get(), &rgba, &end_ms)) {
            throw std::runtime_error("'" + path.string() + "' has a corrupt frame");
        }
        const DecodedFrame frame{framebuffer_from_rgba(rgba, result.width, result.height), previous_end_ms,
                                 end_ms - previous_end_ms};
        previous_end_ms = end_ms;
        if (!visit(frame)) break;
    }
    return result;
}

bool looks_like_webp(std::span<const std::uint8_t> bytes) noexcept {
    constexpr std::string_view riff = "RIFF", webp = "WEBP";
    const auto matches = [&](std::size_t at, std::string_view tag) {
        return bytes.size() >= at + tag.size() && std::equal(tag.begin(), tag.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
    };
    return matches(0, riff) && matches(8, webp);
}

Framebuffer decode_webp_still(std::span<const std::uint8_t> bytes, std::size_t max_pixels) {
    WebPBitstreamFeatures features;
    if (WebPGetFeatures(bytes.data(), bytes.size(), &features) != VP8_STATUS_OK) throw std::runtime_error("not a WebP image");
    if (features.has_animation != 0) throw std::runtime_error("an animated WebP, not a still image");
    const auto pixels = static_cast<std::size_t>(features.width) * static_cast<std::size_t>(features.height);
    if (pixels > max_pixels) {
        throw std::runtime_error("image is " + std::to_string(features.width) + "x" + std::to_string(features.height) +
                                 ", more than the " + std::to_string(max_pixels) + " pixels allowed");
    }
    int width = 0, height = 0;
    const std::unique_ptr<std::uint8_t, void (*)(void*)> rgb(WebPDecodeRGB(bytes.data(), bytes.size(), &width, &height), WebPFree);
    if (!rgb) throw std::runtime_error("corrupt WebP image data");
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    return {width, height, std::vector<std::uint8_t>(rgb.get(), rgb.get() + size)};
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
