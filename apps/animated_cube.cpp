#include "exporter.hpp"

namespace {

// Browsers play frames of 10 ms or less at 100 ms, so the fastest honest rate gives 11 ms.
constexpr int kMaxFps = 95;

}  // namespace

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
    add_integer_option(app, "--fps", fps, 1, kMaxFps,
                       "Playback rate, 1..95. WebP stores whole milliseconds, so a frame lasts "
                       "round(1000 / fps) ms; browsers play frames of 10 ms or less at 100 ms, "
                       "so faster rates would play slower");

    return run_exporter(app, options, argc, argv, [&] {
        check_output(app, options);
        const int spacing_ms = (1000 + fps / 2) / fps;
        raster::AnimationEncoder encoder(options.width, options.height, spacing_ms, options.effort);
        raster::Framebuffer frame(options.width, options.height);
        Progress progress(app.get_name(), options);
        for (int i = 0; i < frames; ++i) {
            raster::render_tumble_frame(frame, i, frames, style);
            encoder.add_frame(frame);
            progress.frame(i + 1, frames);
        }
        progress.stage("assembling the animation");
        const std::vector<std::uint8_t> bytes = encoder.finish();
        deliver(options, bytes);
        return describe_animation(options, frames, std::int64_t{frames} * spacing_ms, bytes.size());
    });
}
