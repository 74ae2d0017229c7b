// Encoding WebP stills and animations, and decoding a still; webp_reader.cpp decodes animations
// frame by frame and webp_parts.cpp joins parts.
#include <raster/io/webp.hpp>

#include "io/task_pool.hpp"
#include "io/webp_chunks.hpp"

#include <algorithm>
#include <deque>
#include <fstream>
#include <future>
#include <optional>
#include <thread>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <webp/decode.h>
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

// Each frame's own lossless settings on the parallel path, chosen from the encode lab's Pareto
// front (doc/performance.md): the changed rectangles are small, so a lighter method costs
// little size.
WebPConfig parallel_config(Effort effort) {
    WebPConfig config = lossless_config(effort);
    if (effort != Effort::max) {  // method 0 and 1 at quality 50: on the front for fast and default
        config.method = effort == Effort::fast ? 0 : 1;
        config.quality = 50.0F;
    }
    return config;
}

// A WebPPicture holding a copy of the frame's pixels, freed on scope exit.
struct Picture {
    WebPPicture picture;

    Picture(const Framebuffer& image, std::span<const std::uint8_t> alpha) {
        if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp version mismatch");
        picture.use_argb = 1;
        picture.width = image.width();
        picture.height = image.height();
        const bool imported = alpha.empty() ? WebPPictureImportRGB(&picture, image.bytes().data(), image.width() * 3) != 0
                                            : WebPPictureImportRGBA(&picture, rgba_bytes(image, alpha).data(), image.width() * 4) != 0;
        if (!imported) {
            throw std::runtime_error("out of memory importing a frame");
        }
    }
    ~Picture() { WebPPictureFree(&picture); }
    Picture(const Picture&) = delete;
    Picture& operator=(const Picture&) = delete;
};

// The lossless bytes of one picture: a whole frame, or the rectangle of it that changed.
// `channels` is 3 for RGB, 4 for RGBA whose transparent pixels show the frame below.
std::vector<std::uint8_t> encode_lossless(const std::uint8_t* rgb, int width, int height, int stride, const WebPConfig& config,
                                          int channels = 3) {
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp version mismatch");
    picture.use_argb = 1;
    picture.width = width;
    picture.height = height;
    const std::unique_ptr<WebPPicture, void (*)(WebPPicture*)> owned(&picture, WebPPictureFree);
    const int imported = channels == 4 ? WebPPictureImportRGBA(&picture, rgb, stride) : WebPPictureImportRGB(&picture, rgb, stride);
    if (!imported) throw std::runtime_error("out of memory importing a frame");
    WebPMemoryWriter memory;
    WebPMemoryWriterInit(&memory);
    picture.writer = WebPMemoryWrite;
    picture.custom_ptr = &memory;
    const bool encoded = WebPEncode(&config, &picture) != 0;
    std::vector<std::uint8_t> bytes(memory.mem, memory.mem + memory.size);
    WebPMemoryWriterClear(&memory);
    if (!encoded) throw std::runtime_error("cannot encode a frame: libwebp error " + std::to_string(picture.error_code));
    return bytes;
}

}  // namespace

std::vector<std::uint8_t> encode_webp_still(const Framebuffer& image, Effort effort, std::span<const std::uint8_t> alpha) {
    if (alpha.empty()) return encode_lossless(image.bytes().data(), image.width(), image.height(), image.width() * 3, lossless_config(effort));
    return encode_lossless(rgba_bytes(image, alpha).data(), image.width(), image.height(), image.width() * 4, lossless_config(effort), 4);
}

std::uintmax_t write_webp_still(const Framebuffer& image, const std::filesystem::path& path,
                                Effort effort, OutputPolicy policy) {
    check_output_path(path, policy);
    const std::vector<std::uint8_t> bytes = encode_webp_still(image, effort);
    write_output_file(path, bytes, policy);
    return bytes.size();
}

namespace {

// The smallest rectangle holding every pixel that differs between two frames of one size, its
// corner moved up and left to even coordinates (WebP stores frame offsets halved); one pixel at
// the origin when nothing changed, so that every frame keeps its place in the file.
struct Region {
    int x = 0, y = 0, width = 1, height = 1;
};

Region changed_region(const Framebuffer& before, const Framebuffer& after) {
    const int w = after.width(), h = after.height();
    const auto row_bytes = static_cast<std::size_t>(w) * 3;
    const std::uint8_t* a = before.bytes().data();
    const std::uint8_t* b = after.bytes().data();
    int top = h, bottom = -1, left = w, right = -1;
    const auto same = [](const std::uint8_t* p, const std::uint8_t* q) { return p[0] == q[0] && p[1] == q[1] && p[2] == q[2]; };
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* ra = a + static_cast<std::size_t>(y) * row_bytes;
        const std::uint8_t* rb = b + static_cast<std::size_t>(y) * row_bytes;
        if (std::equal(ra, ra + row_bytes, rb)) continue;
        top = std::min(top, y);
        bottom = y;
        // Only what would widen the rectangle is looked at: left of it, and right of it.
        int x0 = 0;
        while (x0 < left && same(ra + x0 * 3, rb + x0 * 3)) ++x0;
        left = std::min(left, x0);
        int x1 = w - 1;
        while (x1 > right && same(ra + x1 * 3, rb + x1 * 3)) --x1;
        right = std::max(right, x1);
    }
    if (bottom < 0) return {};
    const int x = left & ~1, y = top & ~1;
    return {x, y, right + 1 - x, bottom + 1 - y};
}

struct EncodedFrame {
    std::vector<std::uint8_t> bytes;
    Region region;
    bool blend;  // drawn over the previous frame, its transparent pixels showing it
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
    // The parallel path: the last frame, the encodes in flight in frame order, and the file so far.
    std::size_t threads = 1;
    bool try_blending = false;  // Effort::max: each frame both opaque and blended, the smaller kept
    std::optional<Framebuffer> previous;
    std::unique_ptr<detail::TaskPool<EncodedFrame>> pool;
    std::deque<std::future<EncodedFrame>> in_flight;
    // The file so far, frames appended in one pass: libwebp's muxer walks its list per frame.
    std::optional<detail::AnimationAssembler> assembled;

    State(int w, int h, int spacing, AnimationSettings settings)
        : width(w), height(h), frame_spacing_ms(spacing), config(lossless_config(settings.effort)), path(settings.path) {
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
            throw std::invalid_argument("animation size must be 1.." + std::to_string(kMaxImageSide) +
                                        " on each side, got " + std::to_string(w) + "x" + std::to_string(h));
        }
        if (spacing < 1 || spacing > kMaxFrameSpacingMs) {
            throw std::invalid_argument("frame spacing must be 1.." + std::to_string(kMaxFrameSpacingMs) +
                                        " ms, got " + std::to_string(spacing));
        }
        if (settings.threads < 0) throw std::invalid_argument("thread count must be 0 (every core) or more");
        if (settings.tuning) {
            const LosslessTuning& t = *settings.tuning;
            if (t.method < 0 || t.method > 6 || !(t.quality >= 0.0F && t.quality <= 100.0F)) {
                throw std::invalid_argument("lossless tuning needs a method 0..6 and a quality 0..100");
            }
        }
        if (path == AnimationPath::parallel) {
            config = parallel_config(settings.effort);
            if (settings.tuning) config.method = settings.tuning->method, config.quality = settings.tuning->quality;
            // Frames in flight follow the cores, not the count asked for: more would only hold memory.
            const std::size_t cores = std::max(1U, std::thread::hardware_concurrency());
            threads = settings.threads > 0 ? std::min(static_cast<std::size_t>(settings.threads), cores) : cores;
            try_blending = settings.effort == Effort::max;
            pool = std::make_unique<detail::TaskPool<EncodedFrame>>(threads);
            assembled.emplace(width, height, 0xFF000000U, 0);  // opaque black background, loop forever
            return;
        }
        if (settings.tuning) config.method = settings.tuning->method, config.quality = settings.tuning->quality;
        WebPAnimEncoderOptions options;
        if (!WebPAnimEncoderOptionsInit(&options)) throw std::runtime_error("libwebp version mismatch");
        options.minimize_size = settings_for(settings.effort).minimize_size ? 1 : 0;
        options.allow_mixed = 0;
        options.anim_params.loop_count = 0;
        options.anim_params.bgcolor = 0xFF000000U;  // opaque black, ARGB
        encoder = WebPAnimEncoderNew(width, height, &options);
        if (encoder == nullptr) throw std::runtime_error("cannot start the WebP animation encoder");
    }
    ~State() {
        pool.reset();  // finishes the encodes still queued, then stops its threads
        in_flight.clear();
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

    // Starts encoding a frame's changed rectangle; waits for the oldest encode while too many run.
    void add_in_parallel(const Framebuffer& frame) {
        const Region region = previous ? changed_region(*previous, frame) : Region{0, 0, width, height};
        // The task gets its own copy of the rectangle, so the caller may reuse the frame at once.
        // At the highest effort it also gets the rectangle with the pixels the previous frame
        // already shows made transparent, to be blended over it, and keeps whichever encodes
        // smaller: that wins for slow motion, where little of the rectangle changes.
        const bool try_blend = try_blending && previous.has_value();
        const std::size_t area = static_cast<std::size_t>(region.width) * static_cast<std::size_t>(region.height);
        std::vector<std::uint8_t> opaque(area * 3), blended(try_blend ? area * 4 : 0);
        std::uint8_t* to = opaque.data();
        std::uint8_t* faded = blended.data();
        for (int y = 0; y < region.height; ++y) {
            const std::size_t at = (static_cast<std::size_t>(region.y + y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(region.x)) * 3;
            const std::uint8_t* now = frame.bytes().data() + at;
            const std::uint8_t* before = try_blend ? previous->bytes().data() + at : nullptr;
            std::copy(now, now + static_cast<std::size_t>(region.width) * 3, to);
            to += static_cast<std::size_t>(region.width) * 3;
            if (!try_blend) continue;
            for (int x = 0; x < region.width; ++x, now += 3) {
                const bool unchanged = before[0] == now[0] && before[1] == now[1] && before[2] == now[2];
                faded[0] = unchanged ? 0 : now[0], faded[1] = unchanged ? 0 : now[1], faded[2] = unchanged ? 0 : now[2];
                faded[3] = unchanged ? 0 : 255;
                before += 3, faded += 4;
            }
        }
        in_flight.push_back(pool->submit([opaque = std::move(opaque), blended = std::move(blended), region, config = config] {
            EncodedFrame best{encode_lossless(opaque.data(), region.width, region.height, region.width * 3, config), region, false};
            if (!blended.empty()) {
                WebPConfig see_through = config;
                see_through.exact = 0;  // what lies under a transparent pixel is never seen
                std::vector<std::uint8_t> bytes = encode_lossless(blended.data(), region.width, region.height, region.width * 4, see_through, 4);
                if (bytes.size() < best.bytes.size()) best = {std::move(bytes), region, true};
            }
            return best;
        }));
        const auto row = static_cast<std::size_t>(region.width) * 3;
        if (previous) {
            // Outside the rectangle the frames agree: only the rectangle needs copying.
            for (int y = region.y; y < region.y + region.height; ++y) {
                const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(region.x)) * 3;
                std::copy(frame.bytes().begin() + static_cast<std::ptrdiff_t>(at), frame.bytes().begin() + static_cast<std::ptrdiff_t>(at + row),
                          previous->pixels() + at);
            }
        } else {
            previous.emplace(frame);
        }
        while (in_flight.size() > threads) collect_oldest();
    }

    // Appends the oldest finished encode to the file, in frame order.
    void collect_oldest() {
        const EncodedFrame encoded = in_flight.front().get();
        in_flight.pop_front();
        detail::AnimationFrame frame;
        frame.x = encoded.region.x;
        frame.y = encoded.region.y;
        frame.width = encoded.region.width;
        frame.height = encoded.region.height;
        frame.duration_ms = frame_spacing_ms;
        frame.blend = encoded.blend;  // transparent pixels keep what was there
        frame.image = detail::picture_in(std::span<const std::uint8_t>(encoded.bytes).subspan(12));  // the still's VP8L chunk
        WebPBitstreamFeatures features;
        if (frame.image.empty() || WebPGetFeatures(frame.image.data(), frame.image.size(), &features) != VP8_STATUS_OK) {
            throw std::runtime_error("cannot add a frame to the animation");
        }
        assembled->add_frame(frame, features.has_alpha != 0);
    }

    std::vector<std::uint8_t> assemble_parallel() {
        while (!in_flight.empty()) collect_oldest();
        return std::move(*assembled).finish();
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
        state_->add_in_parallel(frame);
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
        if (!state->previous) throw std::logic_error("an animation needs at least one frame");
        return state->assemble_parallel();
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

AnimationWriter::AnimationWriter(const std::filesystem::path& path, int width, int height,
                                 int frame_spacing_ms, AnimationSettings settings, OutputPolicy policy)
    : path_(path), policy_(policy), encoder_(width, height, frame_spacing_ms, settings) {
    check_output_path(path_, policy_);
}

std::uintmax_t AnimationWriter::finish() {
    const std::vector<std::uint8_t> bytes = encoder_.finish();
    write_output_file(path_, bytes, policy_);
    return bytes.size();
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

}  // namespace raster
