#include "animation_export.hpp"
#include "command_line.hpp"
#include "option_checks.hpp"
#include "scene_option.hpp"
#include "shared_options.hpp"

#include <raster/render/samples.hpp>

int main(int argc, char** argv) {
    CLI::App app("Renders the animation of one diary scene (0.0.8 to 0.1.7; by default the original's final "
                 "animation), or of the Ptah and raster-engine seeds, to a lossless animated WebP that loops forever.",
                 "animated-scene");
    app.footer(scene_list() + "\nExamples:\n"
                              "  animated-scene                           # the original's final animation, 7.2 s\n"
                              "  animated-scene --scene shaders           # Phong and Gouraud side by side\n"
                              "  animated-scene --scene orbit --effort fast orbit.webp\n"
                              "  animated-scene --scene point-light --perspective 60 lamp.webp\n"
                              "  animated-scene --scene flythrough --width 640 --height 360 fly.webp\n"
                              "  animated-scene --scene islands --style wireframe wire.webp");
    ExportOptions options{"animated-scene.webp"};
    add_export_options(app, options);
    add_samples_option(app, options,
                       "1 for the diary's scenes, " + std::to_string(raster::kSmoothSamples) + " for the seeds'");
    std::string name;
    add_scene_option(app, name);
    int frames = 0;
    add_integer_option(app, "--frames", frames, 0, 10000,
                       "Frames in the whole clip, 1..10000; 0 (the default) takes the scene's own count");
    int fps = 1000 / raster::kFrameSpacingMs;
    add_animation_options(app, fps, options);
    bool automatic = false;
    add_detail_option(app, automatic);
    int fov = 0;
    add_perspective_option(app, fov);
    raster::RenderStyle style = raster::RenderStyle::textured;
    add_render_style_option(app, style);

    return run_exporter(app, options, argc, argv, [&] {
        check_seed_options(name, automatic, fov);
        if (options.samples == 0) options.samples = raster::is_seed_scene(name) ? raster::kSmoothSamples : 1;
        if (raster::is_seed_scene(name)) {
            const raster::SeedScene seed(name);
            const int count = frames > 0 ? frames : seed.info().frames;
            raster::Renderer renderer(options.render_options());
            return export_animation(app, options, count, fps, [&](raster::Framebuffer& frame, int index) {
                render_scene(frame, seed.frame(frame.width(), frame.height(), index, count), style, renderer);
            });
        }
        const raster::DiaryScene scene(name);
        const int count = frames > 0 ? frames : scene.info().frames;
        const raster::DetailPlan plan =
            automatic ? plan_for(scene, options.width, options.height, count) : raster::DetailPlan{};
        raster::Renderer renderer(options.render_options());
        return export_animation(
                   app, options, count, fps,
                   [&](raster::Framebuffer& frame, int index) {
                       render_scene(frame,
                                    raster::with_detail(scene.frame(frame.width(), frame.height(), index, count), plan),
                                    fov, style, renderer);
                   }) +
               describe(plan);
    });
}
