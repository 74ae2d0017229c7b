#pragma once

#include "export_options.hpp"

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>
#include <CLI/CLI.hpp>

// Draws a frame and, for a transparent background, fills `alpha` with its coverage (one byte
// per pixel); left empty, the frame is opaque.
using RenderStill = std::function<void(raster::Framebuffer&, std::vector<std::uint8_t>& alpha)>;

// Renders one frame of the chosen size, writes it as a still (WebP or PNG) and returns the line
// to report: "Wrote out.webp: 800x600 still, 4211 bytes".
std::string export_still(const CLI::App& app, const ExportOptions& options, const RenderStill& render);
// A picture encoded and the line that will report it; `written` when it is already on disk.
struct FinishedPicture {
    std::vector<std::uint8_t> bytes;
    std::string report;
    bool written = false;
};
// The same in steps: checks the output and renders now, and returns the step that encodes, which
// may run on another thread while the next picture is drawn; deliver() then writes the bytes.
std::function<FinishedPicture()> render_still(const CLI::App& app, const ExportOptions& options,
                                              const RenderStill& render);
std::string export_still(const CLI::App& app, const ExportOptions& options,
                         const std::function<void(raster::Framebuffer&)>& render);
