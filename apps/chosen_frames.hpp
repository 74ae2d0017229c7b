#pragma once

#include "export_options.hpp"

#include <raster/io/frame_range.hpp>

#include <optional>
#include <string>

// The frames to render: all of them, or --frame-range checked against the clip's length.
[[nodiscard]] std::optional<raster::FrameRange> chosen_range(const ExportOptions& options, int frames, int fps);
// "frames 4..10 of 12", for the report line.
[[nodiscard]] std::string range_text(const raster::FrameRange& range);
