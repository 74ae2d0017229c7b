#include "render_outputs.hpp"

#include "render_option_values.hpp"

#include <raster/io/input_file.hpp>

#include <filesystem>

namespace {

// Named outputs take their format from the name; made names from --format, else WebP.
bool names_its_picture(const CLI::App& app, const RenderArguments& arguments) {
    return arguments.output_dir.empty() && app.count("output") + app.count("--output") > 0;
}

}  // namespace

ImageFormat picture_format(const CLI::App& app, const RenderArguments& arguments) {
    const ExportOptions& options = arguments.options;
    const ImageFormat format =
        names_its_picture(app, arguments) ? options.image_format() : options.format.value_or(ImageFormat::webp);
    if (arguments.plan.frames > 0 && options.frames_dir.empty() && format == ImageFormat::png) {
        throw CLI::ValidationError(
            "a PNG file holds one picture: write the turntable to .webp, or to numbered PNG frames "
            "with --frames-dir DIR");
    }
    return format;
}

void name_the_picture(const CLI::App& app, RenderArguments& arguments, ImageFormat format) {
    ExportOptions& options = arguments.options;
    if (!arguments.more_models.empty()) {
        throw CLI::ValidationError(
            "several models need --output-dir DIR, for example: render a.obj b.glb --output-dir thumbs");
    }
    if (app.count("output") > 0 && looks_like_a_model(options.output)) {
        throw CLI::ValidationError(
            "'" + raster::printable(options.output) +
            "' looks like a model, not a picture to write: give --output-dir DIR to render several "
            "models, or -o to write that name anyway");
    }
    if (!names_its_picture(app, arguments)) {
        options.output = std::filesystem::path(arguments.model_path).stem().string() + file_extension(format);
        options.format = format;
    }
}
