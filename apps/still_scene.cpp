#include "exporter.hpp"
#include "scene_option.hpp"

int main(int argc, char** argv) {
    CLI::App app("Renders the still of one diary scene (0.0.8 to 0.1.7; by default the original's final scene), or of the Ptah and "
                 "raster-engine seeds, to a lossless WebP.", "still-scene");
    app.footer(scene_list() +
               "\nExamples:\n"
               "  still-scene                              # point-lights -> still-scene.webp\n"
               "  still-scene --scene two-spheres spheres.webp\n"
               "  still-scene --scene point-light --perspective 50 lamp.webp\n"
               "  still-scene --scene ptah ptah.webp\n"
               "  still-scene --scene materials --detail auto --width 1280 --height 720 m.webp");
    ExportOptions options{"still-scene.webp"};
    add_export_options(app, options);
    add_samples_option(app, options, "1 for the diary's scenes, " + std::to_string(raster::kSmoothSamples) + " for the seeds'");
    std::string name;
    add_scene_option(app, name);
    bool automatic = false;
    add_detail_option(app, automatic);
    int fov = 0;
    add_perspective_option(app, fov);

    return run_exporter(app, options, argc, argv, [&] {
        check_seed_options(name, automatic, fov);
        if (options.samples == 0) options.samples = raster::is_seed_scene(name) ? raster::kSmoothSamples : 1;
        if (raster::is_seed_scene(name)) {
            const raster::SeedScene seed(name);
            return export_still(app, options, [&](raster::Framebuffer& frame) {
                raster::Renderer(options.render_options()).render(frame, seed.still(frame.width(), frame.height()));
            });
        }
        const raster::DiaryScene scene(name);
        const raster::DetailPlan plan = automatic ? plan_for(scene, options.width, options.height, 0) : raster::DetailPlan{};
        return export_still(app, options, [&](raster::Framebuffer& frame) {
            raster::Renderer renderer(options.render_options());
            render_scene(frame, raster::with_detail(scene.still(frame.width(), frame.height()), plan), fov, renderer);
        }) + describe(plan);
    });
}
