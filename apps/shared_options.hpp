#pragma once

#include "export_options.hpp"

#include <raster/scenes/scenes.hpp>

#include <string>
#include <CLI/CLI.hpp>

// The options several exporters share, each with its help.

// OUTPUT / -o, --format, --effort, --quiet, --progress, --follow-symlinks, --preview.
void add_output_options(CLI::App& app, ExportOptions& options);
// --width and --height, then the output options.
void add_export_options(CLI::App& app, ExportOptions& options);
void add_style_option(CLI::App& app, raster::CubeStyle& style, const std::string& line_colour);
// --samples 1|2|4|8|16, anti-aliasing. Left 0 when not given, for the program to choose its
// default (`default_text` says which in the help).
void add_samples_option(CLI::App& app, ExportOptions& options, const std::string& default_text);
// --fps 1..95, with the browsers' 10 ms rule in its help, --encoder parallel|anim,
// --frames-dir DIR, --frame-range A..B and --skip-existing.
void add_animation_options(CLI::App& app, int& fps, ExportOptions& options);
