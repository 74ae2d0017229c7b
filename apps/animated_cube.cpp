#include "exporter.hpp"

int main(int argc, char** argv) {
    CLI::App app("Renders one full tumble of the cube, M(t) = Rz(t) Ry(t) Rx(t) S(0.5), to a "
                 "lossless animated WebP that loops forever.",
                 "animated-cube");
    app.footer("Examples:\n  animated-cube                             # 360 frames, 50 fps, 7.2 s\n"
               "  animated-cube --style culled-wireframe --effort fast spin.webp");
    ExportOptions options{"animated-cube.webp"};
    add_export_options(app, options);
    raster::CubeStyle style = raster::CubeStyle::filled;
    add_style_option(app, style, "cornflower blue");
    int frames = raster::kAnimationFrameCount;
    app.add_option("--frames", frames, "Frames in one full tumble, 1..10000")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    int fps = 1000 / raster::kFrameSpacingMs;
    app.add_option("--fps", fps,
                   "Playback rate, 1..1000; WebP stores whole milliseconds, so each frame lasts "
                   "round(1000 / fps) ms")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();

    return run_exporter(app, argc, argv, [&] {
        const int spacing_ms = (1000 + fps / 2) / fps;
        raster::AnimationWriter writer(options.output, options.width, options.height, spacing_ms,
                                       options.effort);
        raster::Framebuffer frame(options.width, options.height);
        for (int i = 0; i < frames; ++i) {
            raster::render_tumble_frame(frame, i, frames, style);
            writer.add_frame(frame);
        }
        const std::uintmax_t bytes = writer.finish();
        return describe_animation(options, frames, frames * spacing_ms, bytes);
    });
}
