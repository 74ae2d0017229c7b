#pragma once

#include <raster/image/framebuffer.hpp>

#include "io/task_pool.hpp"
#include "io/webp/changed_region.hpp"
#include "io/webp/chunks.hpp"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <vector>
#include <webp/encode.h>

// The parallel animation path: each frame's changed rectangle encoded losslessly on its own, on
// a pool of threads while later frames render, then appended to the file in frame order.
namespace raster::detail {

struct EncodedFrame {
    std::vector<std::uint8_t> bytes;
    Region region;
    bool blend;  // drawn over the previous frame, its transparent pixels showing it
};

class ParallelFrames {
public:
    // At most `threads` encodes in flight; `try_blending` encodes each frame both opaque and
    // blended over the one before, and keeps the smaller.
    ParallelFrames(int width, int height, int frame_spacing_ms, const WebPConfig& config, std::size_t threads,
                   bool try_blending);
    ~ParallelFrames();
    ParallelFrames(const ParallelFrames&) = delete;
    ParallelFrames& operator=(const ParallelFrames&) = delete;

    // Starts encoding a frame's changed rectangle; waits for the oldest encode while too many run.
    void add(const Framebuffer& frame);
    [[nodiscard]] bool has_frames() const noexcept { return previous_.has_value(); }
    // Waits for every encode and returns the file.
    [[nodiscard]] std::vector<std::uint8_t> finish();

private:
    // Appends the oldest finished encode to the file, in frame order.
    void collect_oldest();

    int width_;
    int height_;
    int frame_spacing_ms_;
    WebPConfig config_;
    std::size_t threads_;
    bool try_blending_;  // Effort::max: each frame both opaque and blended, the smaller kept
    // The last frame, the encodes in flight in frame order, and the file so far.
    std::optional<Framebuffer> previous_;
    std::unique_ptr<TaskPool<EncodedFrame>> pool_;
    std::deque<std::future<EncodedFrame>> in_flight_;
    // The file so far, frames appended in one pass: libwebp's muxer walks its list per frame.
    AnimationAssembler assembled_;
};

}  // namespace raster::detail
