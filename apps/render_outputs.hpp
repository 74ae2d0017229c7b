#pragma once

#include "export_options.hpp"
#include "render_options.hpp"

#include <CLI/CLI.hpp>

// Where render's pictures go and in which format.

// A named output's own format, or --format's, else WebP. A turntable must go to WebP or to
// numbered PNG frames (CLI::ValidationError).
ImageFormat picture_format(const CLI::App& app, const RenderArguments& arguments);
// A single model's picture: refuses more models without --output-dir and an output named like a
// model, and names an unnamed picture after the model, in the working directory.
void name_the_picture(const CLI::App& app, RenderArguments& arguments, ImageFormat format);
