// The only file that includes libwebp.
#include <raster/webp.hpp>

#include "atomic_file.hpp"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
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

std::uintmax_t write_webp_still(const Framebuffer& image, const std::filesystem::path& path,
                                Effort effort) {
    AtomicFile file(path);
    const WebPConfig config = lossless_config(effort);
    Picture frame(image);
    WebPMemoryWriter memory;
    WebPMemoryWriterInit(&memory);
    frame.picture.writer = WebPMemoryWrite;
    frame.picture.custom_ptr = &memory;
    const bool encoded = WebPEncode(&config, &frame.picture) != 0;
    const std::vector<std::uint8_t> bytes(memory.mem, memory.mem + memory.size);
    WebPMemoryWriterClear(&memory);
    if (!encoded) {
        throw std::runtime_error("cannot encode '" + path.string() + "': libwebp error " +
                                 std::to_string(frame.picture.error_code));
    }
    file.commit(bytes);
    return bytes.size();
}

struct AnimationWriter::State {
    AtomicFile file;
    std::filesystem::path path;
    int width;
    int height;
    int frame_spacing_ms;
    int next_timestamp_ms = 0;
    WebPConfig config;
    WebPAnimEncoder* encoder = nullptr;

    State(const std::filesystem::path& destination, int w, int h, int spacing, Effort effort)
        : file(destination), path(destination), width(w), height(h), frame_spacing_ms(spacing),
          config(lossless_config(effort)) {
        if (spacing < 1) throw std::invalid_argument("frame spacing must be at least 1 ms");
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

    [[noreturn]] void fail(const std::string& what) {
        throw std::runtime_error("cannot encode '" + path.string() + "': " + what + ": " +
                                 WebPAnimEncoderGetError(encoder));
    }
};

AnimationWriter::AnimationWriter(const std::filesystem::path& path, int width, int height,
                                 int frame_spacing_ms, Effort effort)
    : state_(std::make_unique<State>(path, width, height, frame_spacing_ms, effort)) {}

AnimationWriter::~AnimationWriter() = default;
AnimationWriter::AnimationWriter(AnimationWriter&&) noexcept = default;
AnimationWriter& AnimationWriter::operator=(AnimationWriter&&) noexcept = default;

void AnimationWriter::add_frame(const Framebuffer& frame) {
    if (!state_) throw std::logic_error("AnimationWriter used after finish()");
    if (frame.width() != state_->width || frame.height() != state_->height) {
        throw std::invalid_argument("frame size differs from the animation's");
    }
    Picture picture(frame);
    if (!WebPAnimEncoderAdd(state_->encoder, &picture.picture, state_->next_timestamp_ms,
                            &state_->config)) {
        state_->fail("frame at " + std::to_string(state_->next_timestamp_ms) + " ms");
    }
    state_->next_timestamp_ms += state_->frame_spacing_ms;
}

std::uintmax_t AnimationWriter::finish() {
    if (!state_) throw std::logic_error("AnimationWriter::finish() called twice");
    const std::unique_ptr<State> state = std::move(state_);
    // A last empty add sets the final frame's duration to one full spacing.
    if (!WebPAnimEncoderAdd(state->encoder, nullptr, state->next_timestamp_ms, nullptr)) {
        state->fail("end of animation");
    }
    WebPData data;
    WebPDataInit(&data);
    if (!WebPAnimEncoderAssemble(state->encoder, &data)) state->fail("assembling");
    const std::vector<std::uint8_t> bytes(data.bytes, data.bytes + data.size);
    WebPDataClear(&data);
    state->file.commit(bytes);
    return bytes.size();
}

DecodedWebp read_webp(const std::filesystem::path& path) {
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
    DecodedWebp result{static_cast<int>(info.canvas_width), static_cast<int>(info.canvas_height), {}};
    int previous_end_ms = 0;
    while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
        std::uint8_t* rgba = nullptr;
        int end_ms = 0;
        if (!WebPAnimDecoderGetNext(decoder.get(), &rgba, &end_ms)) {
            throw std::runtime_error("'" + path.string() + "' has a corrupt frame");
        }
        result.frames.push_back({framebuffer_from_rgba(rgba, result.width, result.height),
                                 previous_end_ms, end_ms - previous_end_ms});
        previous_end_ms = end_ms;
    }
    return result;
}

}  // namespace raster
