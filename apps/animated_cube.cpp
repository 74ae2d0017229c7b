#include "animation_export.hpp"
#include "command_line.hpp"
#include "option_checks.hpp"
#include "shared_options.hpp"

int main(int argc, char** argv) {
    CLI::App app("Renders one full tumble of the cube, M(t) = Rz(t) Ry(t) Rx(t) S(0.5), to a "
                 "lossless animated WebP that loops forever.",
                 "animated-cube");
    app.footer("Examples:\n"
               "  animated-cube                         # 360 frames, 50 fps, 7.2 s\n"
               "  animated-cube --style culled-wireframe --effort fast spin.webp\n"
               "  animated-cube --frames 60 -o - | webpinfo /dev/stdin");
    ExportOptions options{"animated-cube.webp"};
    add_export_options(app, options);
    raster::CubeStyle style = raster::CubeStyle::filled;
    add_style_option(app, style, "cornflower blue");
    int frames = raster::kAnimationFrameCount;
    add_integer_option(app, "--frames", frames, 1, 10000, "Frames in one full tumble, 1..10000");
    int fps = 1000 / raster::kFrameSpacingMs;
    add_animation_options(app, fps, options);

    return run_exporter(app, options, argc, argv, [&] {
        return export_animation(app, options, frames, fps, [&](raster::Framebuffer& frame, int index) {
            raster::render_tumble_frame(frame, index, frames, style);
        });
    });
}
