#include "io/webp/parallel_frames.hpp"

#include "io/webp/lossless_picture.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <webp/decode.h>

namespace raster::detail {

ParallelFrames::ParallelFrames(int width, int height, int frame_spacing_ms, const WebPConfig& config,
                               std::size_t threads, bool try_blending)
    : width_(width), height_(height), frame_spacing_ms_(frame_spacing_ms), config_(config), threads_(threads),
      try_blending_(try_blending), pool_(std::make_unique<TaskPool<EncodedFrame>>(threads)),
      assembled_(width, height, 0xFF000000U, 0) {}  // opaque black background, loop forever

ParallelFrames::~ParallelFrames() {
    pool_.reset();  // finishes the encodes still queued, then stops its threads
    in_flight_.clear();
}

void ParallelFrames::add(const Framebuffer& frame) {
    const Region region = previous_ ? changed_region(*previous_, frame) : Region{0, 0, width_, height_};
    // The task gets its own copy of the rectangle, so the caller may reuse the frame at once.
    // At the highest effort it also gets the rectangle with the pixels the previous frame
    // already shows made transparent, to be blended over it, and keeps whichever encodes
    // smaller: that wins for slow motion, where little of the rectangle changes.
    const bool try_blend = try_blending_ && previous_.has_value();
    const std::size_t area = static_cast<std::size_t>(region.width) * static_cast<std::size_t>(region.height);
    std::vector<std::uint8_t> opaque(area * 3), blended(try_blend ? area * 4 : 0);
    std::uint8_t* to = opaque.data();
    std::uint8_t* faded = blended.data();
    for (int y = 0; y < region.height; ++y) {
        const std::size_t at = (static_cast<std::size_t>(region.y + y) * static_cast<std::size_t>(width_) +
                                static_cast<std::size_t>(region.x)) *
                               3;
        const std::uint8_t* now = frame.bytes().data() + at;
        const std::uint8_t* before = try_blend ? previous_->bytes().data() + at : nullptr;
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
    in_flight_.push_back(
        pool_->submit([opaque = std::move(opaque), blended = std::move(blended), region, config = config_] {
            EncodedFrame best{encode_lossless(opaque.data(), region.width, region.height, region.width * 3, config),
                              region, false};
            if (!blended.empty()) {
                WebPConfig see_through = config;
                see_through.exact = 0;  // what lies under a transparent pixel is never seen
                std::vector<std::uint8_t> bytes =
                    encode_lossless(blended.data(), region.width, region.height, region.width * 4, see_through, 4);
                if (bytes.size() < best.bytes.size()) best = {std::move(bytes), region, true};
            }
            return best;
        }));
    const auto row = static_cast<std::size_t>(region.width) * 3;
    if (previous_) {
        // Outside the rectangle the frames agree: only the rectangle needs copying.
        for (int y = region.y; y < region.y + region.height; ++y) {
            const std::size_t at =
                (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(region.x)) *
                3;
            std::copy(frame.bytes().begin() + static_cast<std::ptrdiff_t>(at),
                      frame.bytes().begin() + static_cast<std::ptrdiff_t>(at + row), previous_->pixels() + at);
        }
    } else {
        previous_.emplace(frame);
    }
    while (in_flight_.size() > threads_) collect_oldest();
}

void ParallelFrames::collect_oldest() {
    const EncodedFrame encoded = in_flight_.front().get();
    in_flight_.pop_front();
    AnimationFrame frame;
    frame.x = encoded.region.x;
    frame.y = encoded.region.y;
    frame.width = encoded.region.width;
    frame.height = encoded.region.height;
    frame.duration_ms = frame_spacing_ms_;
    frame.blend = encoded.blend;  // transparent pixels keep what was there
    frame.image = picture_in(std::span<const std::uint8_t>(encoded.bytes).subspan(12));  // the still's VP8L chunk
    WebPBitstreamFeatures features;
    if (frame.image.empty() || WebPGetFeatures(frame.image.data(), frame.image.size(), &features) != VP8_STATUS_OK) {
        throw std::runtime_error("cannot add a frame to the animation");
    }
    assembled_.add_frame(frame, features.has_alpha != 0);
}

std::vector<std::uint8_t> ParallelFrames::finish() {
    while (!in_flight_.empty()) collect_oldest();
    return std::move(assembled_).finish();
}

}  // namespace raster::detail
