// Animations: libwebp's animation encoder on one thread, or each frame's changed rectangle
// encoded on a pool of threads and assembled in order (the parallel path).
#include <raster/io/webp.hpp>
#include <raster/platform/cores.hpp>

#include "io/webp/parallel_frames.hpp"
#include "io/webp/presets.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <webp/encode.h>
#include <webp/mux.h>

namespace raster {
namespace {

// A WebPPicture holding a copy of the frame's pixels, freed on scope exit.
struct Picture {
    WebPPicture picture;

    Picture(const Framebuffer& image, std::span<const std::uint8_t> alpha) {
        if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp version mismatch");
        picture.use_argb = 1;
        picture.width = image.width();
        picture.height = image.height();
        const bool imported =
            alpha.empty() ? WebPPictureImportRGB(&picture, image.bytes().data(), image.width() * 3) != 0
                          : WebPPictureImportRGBA(&picture, rgba_bytes(image, alpha).data(), image.width() * 4) != 0;
        if (!imported) {
            throw std::runtime_error("out of memory importing a frame");
        }
    }
    ~Picture() { WebPPictureFree(&picture); }
    Picture(const Picture&) = delete;
    Picture& operator=(const Picture&) = delete;
};

}  // namespace

struct AnimationEncoder::State {
    int width;
    int height;
    int frame_spacing_ms;
    std::int64_t next_timestamp_ms = 0;
    WebPConfig config;
    AnimationPath path;
    // libwebp's animation encoder (path anim).
    WebPAnimEncoder* encoder = nullptr;
    // The parallel path's frames, encoded on a pool of threads.
    std::optional<detail::ParallelFrames> parallel;

    State(int w, int h, int spacing, AnimationSettings settings)
        : width(w), height(h), frame_spacing_ms(spacing), config(detail::lossless_config(settings.effort)),
          path(settings.path) {
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
            throw std::invalid_argument("animation size must be 1.." + std::to_string(kMaxImageSide) +
                                        " on each side, got " + std::to_string(w) + "x" + std::to_string(h));
        }
        if (spacing < 1 || spacing > kMaxFrameSpacingMs) {
            throw std::invalid_argument("frame spacing must be 1.." + std::to_string(kMaxFrameSpacingMs) + " ms, got " +
                                        std::to_string(spacing));
        }
        if (settings.threads < 0) throw std::invalid_argument("thread count must be 0 (every core) or more");
        if (settings.tuning) {
            const LosslessTuning& t = *settings.tuning;
            if (t.method < 0 || t.method > 6 || !(t.quality >= 0.0F && t.quality <= 100.0F)) {
                throw std::invalid_argument("lossless tuning needs a method 0..6 and a quality 0..100");
            }
        }
        if (path == AnimationPath::parallel) {
            config = detail::parallel_config(settings.effort);
            if (settings.tuning) config.method = settings.tuning->method, config.quality = settings.tuning->quality;
            // Frames in flight follow the cores, not the count asked for: more would only hold memory.
            const auto cores = static_cast<std::size_t>(available_cores());
            const std::size_t threads =
                settings.threads > 0 ? std::min(static_cast<std::size_t>(settings.threads), cores) : cores;
            parallel.emplace(width, height, frame_spacing_ms, config, threads, settings.effort == Effort::max);
            return;
        }
        if (settings.tuning) config.method = settings.tuning->method, config.quality = settings.tuning->quality;
        WebPAnimEncoderOptions options;
        if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("libwebp version mismatch");
        options.minimize_size = detail::minimize_size(settings.effort) ? 1 : 0;
        options.allow_mixed = 0;
        options.anim_params.loop_count = 0;
        options.anim_params.bgcolor = 0xFF000000U;  // opaque black, ARGB
        encoder = WebPAnimEncoderNew(width, height, &options);
        if (encoder == nullptr) throw std::runtime_error("cannot start the WebP animation encoder");
    }
    ~State() {
        parallel.reset();  // finishes the encodes still queued, then stops its threads
        WebPAnimEncoderDelete(encoder);
    }
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

AnimationEncoder::AnimationEncoder(int width, int height, int frame_spacing_ms, AnimationSettings settings)
    : state_(std::make_unique<State>(width, height, frame_spacing_ms, settings)) {}

AnimationEncoder::~AnimationEncoder() = default;
AnimationEncoder::AnimationEncoder(AnimationEncoder&&) noexcept = default;
AnimationEncoder& AnimationEncoder::operator=(AnimationEncoder&&) noexcept = default;

void AnimationEncoder::add_frame(const Framebuffer& frame, std::span<const std::uint8_t> alpha) {
    if (!state_) throw std::logic_error("AnimationEncoder used after finish()");
    if (frame.width() != state_->width || frame.height() != state_->height) {
        throw std::invalid_argument("frame size differs from the animation's");
    }
    const int end_ms = state_->end_of_next_frame();  // the last frame needs its end stamp too
    const auto start_ms = static_cast<int>(state_->next_timestamp_ms);
    if (state_->path == AnimationPath::parallel) {
        // Its changed rectangles are drawn over the frame before; a pixel turned transparent would not show.
        if (!alpha.empty()) throw std::invalid_argument("a transparent animation needs the anim path");
        state_->parallel->add(frame);
    } else {
        Picture picture(frame, alpha);
        if (!WebPAnimEncoderAdd(state_->encoder, &picture.picture, start_ms, &state_->config)) {
            state_->fail("frame at " + std::to_string(start_ms) + " ms");
        }
    }
    state_->next_timestamp_ms = end_ms;
}

std::vector<std::uint8_t> AnimationEncoder::finish() {
    if (!state_) throw std::logic_error("AnimationEncoder::finish() called twice");
    const std::unique_ptr<State> state = std::move(state_);
    if (state->path == AnimationPath::parallel) {
        if (!state->parallel->has_frames()) throw std::logic_error("an animation needs at least one frame");
        return state->parallel->finish();
    }
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

AnimationWriter::AnimationWriter(const std::filesystem::path& path, int width, int height, int frame_spacing_ms,
                                 AnimationSettings settings, OutputPolicy policy)
    : path_(path), policy_(policy), encoder_(width, height, frame_spacing_ms, settings) {
    check_output_path(path_, policy_);
}

std::uintmax_t AnimationWriter::finish() {
    const std::vector<std::uint8_t> bytes = encoder_.finish();
    write_output_file(path_, bytes, policy_);
    return bytes.size();
}

}  // namespace raster
