#pragma once

#include <raster/scenes.hpp>
#include <raster/webp.hpp>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

// What every exporter takes: where to write, how big, how hard to compress.
struct ExportOptions {
    std::filesystem::path output;
    int width = raster::kSceneWidth;
    int height = raster::kSceneHeight;
    raster::Effort effort = raster::Effort::balanced;
};

void add_export_options(CLI::App& app, ExportOptions& options);
void add_style_option(CLI::App& app, raster::CubeStyle& style, const std::string& line_colour);

// Parses the command line and runs `export_file`, which returns the line to report.
// Every failure prints one line to stderr and gives a non-zero exit code.
int run_exporter(CLI::App& app, int argc, char** argv,
                 const std::function<std::string()>& export_file);

// Renders one frame of the chosen size, writes it as a still and returns the line to report:
// "Wrote out.webp: 800x600 still, 4211 bytes".
std::string export_still(const ExportOptions& options, const std::function<void(raster::Framebuffer&)>& render);
// "Wrote out.webp: 800x600, 360 frames, 7200 ms, 205874 bytes"
std::string describe_animation(const ExportOptions& options, int frames, int duration_ms,
                               std::uintmax_t bytes);
