#pragma once

#include "export_options.hpp"
#include "model_render.hpp"

#include <raster/io/reader_service.hpp>

#include <optional>
#include <string>
#include <vector>
#include <CLI/CLI.hpp>
#include <glm/vec3.hpp>

// Everything render's command line says, as its options fill it in.
struct RenderArguments {
    std::string model_path;
    ExportOptions options{"MODEL.webp (or .png with --format png), in the working directory"};
    std::vector<std::string> more_models;
    std::string output_dir;  // --output-dir: a batch
    RenderPlan plan;
    std::optional<glm::dvec3> up;
    std::optional<glm::dvec3> light;
    std::string background;
    std::string max_memory;
    std::string confine;
};

// What render does, for the top of its help.
std::string render_description();
// render's examples and every option, each filling its part of `arguments`.
void add_render_options(CLI::App& app, RenderArguments& arguments);
// Completes the plan from the parsed options, with every model's reader forked from `readers`;
// refuses options that clash (CLI::ValidationError) and reads --texture once for every model.
void settle_arguments(const CLI::App& app, RenderArguments& arguments, const raster::ReaderService& readers);
