#include "command_line.hpp"
#include "scene_option.hpp"
#include "shared_options.hpp"
#include "still_export.hpp"

#include <raster/render/samples.hpp>

#include <stdexcept>

int main(int argc, char** argv) {
    CLI::App app(
        "Renders the still of one diary scene (0.0.8 to 0.1.7; by default the original's final scene), or of the Ptah and "
        "raster-engine seeds, to a lossless WebP.",
        "still-scene");
    app.footer(scene_list() + "\nExamples:\n"
                              "  still-scene                              # point-lights -> still-scene.webp\n"
                              "  still-scene --scene two-spheres spheres.webp\n"
                              "  still-scene --scene point-light --perspective 50 lamp.webp\n"
                              "  still-scene --scene ptah ptah.webp\n"
                              "  still-scene --view waterfall falls.webp  # one element of the islands\n"
                              "  still-scene --scene islands --style flat flat.webp\n"
                              "  still-scene --scene materials --detail auto --width 1280 --height 720 m.webp");
    ExportOptions options{"still-scene.webp"};
    add_export_options(app, options);
    add_samples_option(app, options,
                       "1 for the diary's scenes, " + std::to_string(raster::kSmoothSamples) + " for the seeds'");
    std::string name;
    add_scene_option(app, name);
    bool automatic = false;
    add_detail_option(app, automatic);
    int fov = 0;
    add_perspective_option(app, fov);
    raster::RenderStyle style = raster::RenderStyle::textured;
    add_render_style_option(app, style);
    std::string view;
    add_view_option(app, view);

    return run_exporter(app, options, argc, argv, [&] {
        if (!view.empty()) {
            if (app.count("--scene") > 0 && name != "islands")
                throw std::invalid_argument("--view frames an element of the islands; " + name + " has none");
            name = "islands";
        }
        check_seed_options(name, automatic, fov);
        if (options.samples == 0) options.samples = raster::is_seed_scene(name) ? raster::kSmoothSamples : 1;
        if (raster::is_seed_scene(name)) {
            const raster::SeedScene seed(name);
            return export_still(app, options, [&](raster::Framebuffer& frame) {
                raster::Renderer renderer(options.render_options());
                render_scene(frame,
                             view.empty() ? seed.still(frame.width(), frame.height())
                                          : seed.view(view, frame.width(), frame.height()),
                             style, renderer);
            });
        }
        const raster::DiaryScene scene(name);
        const raster::DetailPlan plan =
            automatic ? plan_for(scene, options.width, options.height, 0) : raster::DetailPlan{};
        return export_still(app, options,
                            [&](raster::Framebuffer& frame) {
                                raster::Renderer renderer(options.render_options());
                                render_scene(frame,
                                             raster::with_detail(scene.still(frame.width(), frame.height()), plan), fov,
                                             style, renderer);
                            }) +
               describe(plan);
    });
}
