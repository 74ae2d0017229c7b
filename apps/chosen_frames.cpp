#include "chosen_frames.hpp"

#include <raster/io/frame_timing.hpp>

#include <stdexcept>

std::optional<raster::FrameRange> chosen_range(const ExportOptions& options, int frames, int fps) {
    if (options.frame_range.empty()) return std::nullopt;
    std::optional<raster::FrameRange> range = raster::frame_range_from_text(options.frame_range);
    if (!range) return std::nullopt;  // the option's own check has refused it
    if (range->last >= frames) {
        throw std::runtime_error("--frame-range " + options.frame_range + " goes past the clip's last frame, " +
                                 std::to_string(frames - 1));
    }
    range->total = frames;
    range->spacing_ms = raster::frame_spacing_ms(fps);
    return range;
}

std::string range_text(const raster::FrameRange& range) {
    return "frames " + std::to_string(range.first) + ".." + std::to_string(range.last) + " of " +
           std::to_string(range.total);
}
