#include "command_line.hpp"
#include "shared_options.hpp"
#include "still_export.hpp"

int main(int argc, char** argv) {
    CLI::App app("Renders the cube in its still pose (pi/4 about Y, then X, half size) to a "
                 "lossless WebP still.",
                 "still-cube");
    app.footer("Examples:\n"
               "  still-cube                          # filled cube -> still-cube.webp\n"
               "  still-cube --style wireframe w.webp  # the 0.0.3 look: 12 white edges");
    ExportOptions options{"still-cube.webp"};
    add_export_options(app, options);
    raster::CubeStyle style = raster::CubeStyle::filled;
    add_style_option(app, style, "white");

    return run_exporter(app, options, argc, argv, [&] {
        return export_still(app, options, [&](raster::Framebuffer& frame) { raster::render_still_cube(frame, style); });
    });
}
