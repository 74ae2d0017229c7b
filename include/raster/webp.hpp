#pragma once

#include <raster/framebuffer.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

// Lossless WebP files: stills, animations, and reading either back. Files are replaced
// atomically; every failure throws std::runtime_error with a one-line reason.
namespace raster {

// How hard the encoder works for a smaller file; doc/performance.md has the measured trade-off.
enum class Effort {
    fast,      // method 0, quality 0, smallest-size search for animations
    balanced,  // method 4, quality 50, smallest-size search for animations: the default
    max,       // method 6, quality 100, smallest-size search: slowest, for a final export
};

// Writes a lossless still; returns the file's size in bytes.
std::uintmax_t write_webp_still(const Framebuffer& image, const std::filesystem::path& path,
                                Effort effort = Effort::balanced);

// Collects frames into a lossless animation that loops forever.
class AnimationWriter {
public:
    // Claims the destination at once, so a bad path fails before any frame is rendered.
    AnimationWriter(const std::filesystem::path& path, int width, int height,
                    int frame_spacing_ms, Effort effort = Effort::balanced);
    ~AnimationWriter();
    AnimationWriter(AnimationWriter&&) noexcept;
    AnimationWriter& operator=(AnimationWriter&&) noexcept;

    // Frame i is shown at i * frame_spacing_ms for frame_spacing_ms.
    void add_frame(const Framebuffer& frame);
    // Encodes, replaces the file, and returns its size in bytes. Call once.
    std::uintmax_t finish();

private:
    struct State;
    std::unique_ptr<State> state_;
};

struct DecodedFrame {
    Framebuffer image;
    int start_ms;
    int duration_ms;
};

struct DecodedWebp {
    int width;
    int height;
    std::vector<DecodedFrame> frames;  // a still decodes as one frame
};

[[nodiscard]] DecodedWebp read_webp(const std::filesystem::path& path);

}  // namespace raster
