#include "command_line.hpp"
#include "shared_options.hpp"
#include "still_export.hpp"

int main(int argc, char** argv) {
    CLI::App app("Renders the unit cube at the identity pose to a lossless WebP still: only the "
                 "near (-Z) face is front-facing, so the picture is one deep-blue square.",
                 "still-unit-cube");
    app.footer("Example:\n  still-unit-cube unit.webp   # a red square would mean culling is backwards");
    ExportOptions options{"still-unit-cube.webp"};
    add_export_options(app, options);

    return run_exporter(app, options, argc, argv, [&] { return export_still(app, options, raster::render_unit_cube); });
}
