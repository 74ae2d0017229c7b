#include "exporter.hpp"

#include <raster/version.hpp>

#include <exception>
#include <iostream>
#include <map>

void add_export_options(CLI::App& app, ExportOptions& options) {
    app.set_version_flag("--version", std::string("raster ") + raster::kVersion);
    app.add_option("output", options.output, "WebP file to write (replaced atomically)")
        ->capture_default_str();
    const std::string side_help = "in pixels, 1.." + std::to_string(raster::kMaxImageSide) +
                                  " (the WebP limit)";
    app.add_option("--width", options.width, "Image width " + side_help)
        ->check(CLI::Range(1, raster::kMaxImageSide))
        ->capture_default_str();
    app.add_option("--height", options.height, "Image height " + side_help)
        ->check(CLI::Range(1, raster::kMaxImageSide))
        ->capture_default_str();
    const std::map<std::string, raster::Effort> efforts{
        {"fast", raster::Effort::fast},
        {"default", raster::Effort::balanced},
        {"max", raster::Effort::max}};
    app.add_option("--effort", options.effort,
                   "Lossless compression effort: fast (quickest, largest file), default "
                   "(small file), max (smallest, much slower)")
        ->transform(CLI::CheckedTransformer(efforts, CLI::ignore_case))
        ->option_text("fast|default|max [default]");
}

void add_style_option(CLI::App& app, raster::CubeStyle& style, const std::string& line_colour) {
    const std::map<std::string, raster::CubeStyle> styles{
        {"filled", raster::CubeStyle::filled},
        {"wireframe", raster::CubeStyle::wireframe},
        {"culled-wireframe", raster::CubeStyle::culled_wireframe}};
    app.add_option("--style", style,
                   "filled: six flat-coloured faces; wireframe: all 12 edges in " + line_colour +
                       "; culled-wireframe: only edges of faces turned toward the camera")
        ->transform(CLI::CheckedTransformer(styles, CLI::ignore_case))
        ->option_text("filled|wireframe|culled-wireframe [filled]");
}

int run_exporter(CLI::App& app, int argc, char** argv,
                 const std::function<std::string()>& export_file) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
        std::cerr << app.get_name() << ": " << error.what() << " (see --help)\n";
        return error.get_exit_code();
    }
    try {
        std::cout << export_file() << '\n';
        return 0;
    } catch (const std::exception& error) {
        std::cerr << app.get_name() << ": " << error.what() << '\n';
        return 1;
    }
}

std::string export_still(const ExportOptions& options, const std::function<void(raster::Framebuffer&)>& render) {
    raster::Framebuffer frame(options.width, options.height);
    render(frame);
    const std::uintmax_t bytes = raster::write_webp_still(frame, options.output, options.effort);
    return "Wrote " + options.output.string() + ": " + std::to_string(options.width) + "x" +
           std::to_string(options.height) + " still, " + std::to_string(bytes) + " bytes";
}

std::string describe_animation(const ExportOptions& options, int frames, int duration_ms,
                               std::uintmax_t bytes) {
    return "Wrote " + options.output.string() + ": " + std::to_string(options.width) + "x" +
           std::to_string(options.height) + ", " + std::to_string(frames) + " frames, " +
           std::to_string(duration_ms) + " ms, " + std::to_string(bytes) + " bytes";
}
