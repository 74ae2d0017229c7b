#pragma once

#include "export_options.hpp"
#include "render_options.hpp"

#include <raster/render/scene.hpp>

#include <chrono>
#include <string>
#include <CLI/CLI.hpp>

// --output-dir: every model drawn into DIR as its name with .webp or .png, the next model read
// while one is drawn and pictures encoded meanwhile. A model that fails is reported in one line
// on stderr and the rest go on; returns the summary line, or throws it when any failed.
std::string render_batch(const CLI::App& app, const RenderArguments& arguments, ImageFormat format,
                         raster::Renderer& renderer, std::chrono::steady_clock::time_point start);
