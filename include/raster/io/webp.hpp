#pragma once

#include <raster/io/input_file.hpp>

#include <raster/image/framebuffer.hpp>
#include <raster/io/output_file.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

// Lossless WebP: stills, animations, and reading either back. Files are written by
// write_output_file (atomic, links and devices refused); every failure throws
// std::runtime_error with a one-line reason. Bodies in src/io/webp/, one file per concept.
namespace raster {

// How hard the encoder works for a smaller file; doc/performance.md has the measured trade-off.
enum class Effort {
    fast,      // method 0, quality 0, smallest-size search for animations
    balanced,  // method 4, quality 50, smallest-size search for animations: the default
    max,       // method 6, quality 100, smallest-size search: slowest, for a final export
};

// The longest frame a WebP animation can hold: its durations are 24-bit milliseconds.
inline constexpr int kMaxFrameSpacingMs = (1 << 24) - 1;

// The bytes of a lossless still .webp file; with `alpha` (one byte per pixel, 255 opaque) it
// keeps transparency.
[[nodiscard]] std::vector<std::uint8_t> encode_webp_still(const Framebuffer& image, Effort effort = Effort::balanced,
                                                          std::span<const std::uint8_t> alpha = {});
// Encodes and writes a lossless still; returns the file's size in bytes.
std::uintmax_t write_webp_still(const Framebuffer& image, const std::filesystem::path& path,
                                Effort effort = Effort::balanced, OutputPolicy policy = {});

// How an animation's frames are compressed (doc/performance.md has the measurements).
enum class AnimationPath {
    // Each frame's changed rectangle encoded losslessly on its own, on a pool of threads while
    // later frames render, then assembled in order: the default.
    parallel,
    // libwebp's animation encoder, on one thread: it also tries blending and merging frames.
    anim,
};

// libwebp's lossless method (0..6) and quality (0..100), for the lab's sweeps.
struct LosslessTuning {
    int method;
    float quality;
};

struct AnimationSettings {
    Effort effort = Effort::balanced;
    AnimationPath path = AnimationPath::parallel;
    int threads = 0;  // frames encoded at once on the parallel path, at most one per core; 0: one per core
    std::optional<LosslessTuning> tuning{};  // replaces the effort's method and quality per frame
};

// Collects frames into the bytes of a lossless animation that loops forever. Every frame of the
// file decodes to exactly the frame given, on either path; the parallel path holds at most
// `threads` frames in flight, so memory does not grow with the frame count.
class AnimationEncoder {
public:
    // Throws std::invalid_argument for a size outside 1..kMaxImageSide, a spacing outside
    // 1..kMaxFrameSpacingMs or a negative thread count.
    AnimationEncoder(int width, int height, int frame_spacing_ms, AnimationSettings settings = {});
    AnimationEncoder(int width, int height, int frame_spacing_ms, Effort effort)
        : AnimationEncoder(width, height, frame_spacing_ms, AnimationSettings{effort}) {}
    ~AnimationEncoder();
    AnimationEncoder(AnimationEncoder&&) noexcept;
    AnimationEncoder& operator=(AnimationEncoder&&) noexcept;

    // Frame i is shown at i * frame_spacing_ms for frame_spacing_ms. Throws std::length_error
    // when the animation would outlast WebP's timestamps (2^31 - 1 ms, about 24.8 days).
    // `alpha` (one byte per pixel) makes the frame's background transparent; only the anim
    // path keeps it, so the parallel path throws std::invalid_argument for it.
    void add_frame(const Framebuffer& frame, std::span<const std::uint8_t> alpha = {});
    // Assembles the animation. Call once.
    [[nodiscard]] std::vector<std::uint8_t> finish();

private:
    struct State;
    std::unique_ptr<State> state_;
};

// An AnimationEncoder that writes its file on finish.
class AnimationWriter {
public:
    // Checks the destination at once, so a bad path fails before any frame is rendered.
    AnimationWriter(const std::filesystem::path& path, int width, int height, int frame_spacing_ms,
                    AnimationSettings settings = {}, OutputPolicy policy = {});
    AnimationWriter(const std::filesystem::path& path, int width, int height, int frame_spacing_ms, Effort effort,
                    OutputPolicy policy = {})
        : AnimationWriter(path, width, height, frame_spacing_ms, AnimationSettings{effort}, policy) {}

    void add_frame(const Framebuffer& frame) { encoder_.add_frame(frame); }
    // Encodes, replaces the file, and returns its size in bytes. Call once.
    std::uintmax_t finish();

private:
    std::filesystem::path path_;
    OutputPolicy policy_;
    AnimationEncoder encoder_;
};

struct DecodedFrame {
    Framebuffer image;
    std::int64_t start_ms;  // the durations before it add up past 2^31 ms in a long enough file
    int duration_ms;
    std::vector<std::uint8_t> alpha;  // one byte per pixel, 255 where opaque
};

struct DecodedWebp {
    int width;
    int height;
    std::vector<DecodedFrame> frames;  // a still decodes as one frame
};

// The largest WebP file read, in bytes.
inline constexpr std::uintmax_t kMaxWebpFileBytes = std::uintmax_t{1} << 30;

// Whether bytes begin like a WebP file (a RIFF container of type WEBP).
[[nodiscard]] bool looks_like_webp(std::span<const std::uint8_t> bytes) noexcept;

// The picture of a still WebP file held in memory, alpha dropped. Throws std::runtime_error with
// a one-line reason for bytes that are not a still WebP, or for more than `max_pixels` pixels
// (checked from the header, before anything is decoded).
[[nodiscard]] Framebuffer decode_webp_still(std::span<const std::uint8_t> bytes, std::size_t max_pixels);

// Decodes every frame into memory; for long animations prefer for_each_webp_frame.
[[nodiscard]] DecodedWebp read_webp(const std::filesystem::path& path);

struct WebpInfo {
    int width;
    int height;
    int frame_count;  // frames in the file
};

// Decodes a WebP file's frames one at a time, each composited onto one canvas as a player shows
// it (blending and disposal as libwebp's WebPAnimDecoder does, pixel for pixel). Besides the
// file it holds the canvas (4 bytes a pixel) and the frame being decoded, whatever the canvas
// size or frame count; the canvas is made when the first frame is decoded.
class WebpFrameReader {
public:
    // Reads the file through InputFile: a regular file of at most kMaxWebpFileBytes that begins
    // like WebP, else one line and nothing read; what was read is appended to `sources` when
    // given. Throws std::runtime_error for a file libwebp's demuxer refuses.
    explicit WebpFrameReader(const std::filesystem::path& path, std::vector<InputRecord>* sources = nullptr);
    ~WebpFrameReader();
    WebpFrameReader(WebpFrameReader&&) noexcept;
    WebpFrameReader& operator=(WebpFrameReader&&) noexcept;

    // The canvas size and frame count, from the headers.
    [[nodiscard]] const WebpInfo& info() const noexcept;
    // The next frame on the canvas, valid until the next call; nullptr after the last. Throws
    // std::runtime_error naming the frame when it does not decode.
    const DecodedFrame* next();

private:
    struct State;
    std::unique_ptr<State> state_;
};

// Decodes frames one at a time (a WebpFrameReader); stops early when `visit` returns false.
// Returns the canvas size and the file's frame count.
WebpInfo for_each_webp_frame(const std::filesystem::path& path, const std::function<bool(const DecodedFrame&)>& visit,
                             std::vector<InputRecord>* sources = nullptr);

}  // namespace raster
