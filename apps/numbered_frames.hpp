#pragma once

#include "animation_export.hpp"

#include <string>
#include <CLI/CLI.hpp>

// --frames-dir: renders the clip (or its --frame-range) as numbered PNG files in that directory,
// skipping with --skip-existing the frames whose files are already whole, and returns the line
// to report: "Wrote f/0000.png to 0359.png: 360 PNG frames of 800x600 for 50 fps, 912345 bytes".
std::string export_numbered_frames(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                                   const RenderFrame& render);
