#pragma once

#include "export_options.hpp"

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>
#include <CLI/CLI.hpp>

// Draws frame `index` and, for a transparent background, fills `alpha` with its coverage (one
// byte per pixel); left empty, the frame is opaque.
using RenderFrame = std::function<void(raster::Framebuffer&, int index, std::vector<std::uint8_t>& alpha)>;

// Renders `frames` frames at `fps` into a looping animation, writes it and returns the line to
// report: "Wrote out.webp: 800x600, 360 frames, 7200 ms, 205874 bytes". With --frames-dir the
// frames are numbered PNG files in that directory instead.
// With --frame-range only those frames are rendered, exactly as in the whole run, into an
// animation marked with its range (webp_parts.hpp) or into their own numbered files.
std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                             const RenderFrame& render);
std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                             const std::function<void(raster::Framebuffer&, int)>& render);
