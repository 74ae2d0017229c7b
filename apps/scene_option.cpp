#include "scene_option.hpp"

#include "option_checks.hpp"

#include <stdexcept>
#include <vector>

void add_scene_option(CLI::App& app, std::string& scene) {
    std::vector<std::string> names;
    for (const raster::SceneInfo& info : raster::diary_scenes()) names.emplace_back(info.name);
    scene = std::string(raster::final_diary_scene().name);
    for (const raster::SeedSceneInfo& info : raster::seed_scenes()) names.emplace_back(info.name);
    app.add_option("--scene", scene, "Which scene of the diary or of the other seeds to render (listed below)")
        ->transform(one_of(names))
        ->option_text("NAME [" + scene + "]");
}

std::string scene_list() {
    std::string list = "Scenes (the original release each one re-creates):\n";
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        std::string name(info.name);
        std::string release(info.release);
        name.resize(16, ' ');
        release.resize(8, ' ');
        list += "  " + name + release + std::string(info.title) + "\n";
    }
    list += "The default, " + std::string(raster::final_diary_scene().name) +
            ", is also the original's final animation (0.1.7 to 0.1.9 drew it through their shaders).\n";
    list += "The other seeds' scenes, in their own perspective cameras:\n";
    for (const raster::SeedSceneInfo& info : raster::seed_scenes()) {
        std::string name(info.name);
        name.resize(16, ' ');
        list += "  " + name + std::string(info.source) + ": " + std::string(info.title) + "\n";
    }
    return list;
}

void add_detail_option(CLI::App& app, bool& automatic) {
    add_choice_option<bool>(app, "--detail", automatic, {{"diary", false}, {"auto", true}},
                            "diary: each release's own mesh and shading; auto: per sphere or torus, the "
                            "coarsest mesh whose outline is within half a pixel of the true one and the "
                            "cheapest shading within one 8-bit level of the exact surface",
                            "diary");
}

raster::DetailPlan plan_for(const raster::DiaryScene& scene, int width, int height, int frames) {
    std::vector<raster::Scene> samples;
    if (frames == 0) {
        samples.push_back(scene.still(width, height));
    } else {
        for (int i = 0; i < frames; i += 30) samples.push_back(scene.frame(width, height, i, frames));
    }
    return raster::plan_detail(samples);
}

std::string describe(const raster::DetailPlan& plan) {
    static constexpr const char* kMethods[] = {"flat", "Gouraud", "Phong"};
    std::string text;
    for (const auto& choice : plan.choices) {
        if (!choice) continue;
        text += (text.empty() ? ", detail " : " and ") + std::string("level ") + std::to_string(choice->level) + " " +
                kMethods[static_cast<int>(choice->shading)];
    }
    return text;
}

void check_seed_options(const std::string& scene, bool automatic, int fov_degrees) {
    if (!raster::is_seed_scene(scene)) return;
    if (automatic)
        throw std::invalid_argument("--detail auto plans the diary's spheres and tori; " + scene + " has none");
    if (fov_degrees != 0)
        throw std::invalid_argument("--perspective applies to the diary's scenes; " + scene + " has its own camera");
}

void add_perspective_option(CLI::App& app, int& fov_degrees) {
    add_integer_option(app, "--perspective", fov_degrees, 0, 179,
                       "0 (the default): the diary's orthographic camera; 1..179: a perspective camera "
                       "with this vertical field of view in degrees, moved back along its line of sight "
                       "so that the scene keeps its framing (small angles look orthographic, wide ones "
                       "close up)");
}

void add_render_style_option(CLI::App& app, raster::RenderStyle& style) {
    add_choice_option<raster::RenderStyle>(
        app, "--style", style,
        {{"textured", raster::RenderStyle::textured},
         {"flat", raster::RenderStyle::flat},
         {"wireframe", raster::RenderStyle::wireframe}},
        "raster-engine's render modes. textured: the scene as it is; flat: each surface in its texture's mean colour, lit "
        "once per facet; wireframe: the edges of the facets facing the eye, one-pixel lines in each surface's colour "
        "(not anti-aliased, whatever --samples says)",
        "textured");
}

namespace {

template <typename Camera>
void render_in_style(raster::Framebuffer& frame, const raster::BasicScene<Camera>& scene, raster::RenderStyle style,
                     raster::Renderer& renderer) {
    switch (style) {
    case raster::RenderStyle::textured: renderer.render(frame, scene); break;
    case raster::RenderStyle::flat: renderer.render(frame, raster::flat_style(scene)); break;
    case raster::RenderStyle::wireframe: raster::draw_wireframe(frame, scene); break;
    }
}

}  // namespace

void render_scene(raster::Framebuffer& frame, const raster::PerspectiveScene& scene, raster::RenderStyle style,
                  raster::Renderer& renderer) {
    render_in_style(frame, scene, style, renderer);
}

void render_scene(raster::Framebuffer& frame, const raster::Scene& scene, int fov_degrees, raster::RenderStyle style,
                  raster::Renderer& renderer) {
    if (fov_degrees != 0) {
        render_in_style(frame, raster::in_perspective(scene, frame.width(), frame.height(), fov_degrees), style,
                        renderer);
    } else {
        render_in_style(frame, scene, style, renderer);
    }
}

void add_view_option(CLI::App& app, std::string& element) {
    std::vector<std::string> names;
    std::string list;
    for (const raster::IslandElement& item : raster::island_elements()) {
        names.emplace_back(item.name);
        std::string name(item.name);
        name.resize(16, ' ');
        list += "\n  " + name + std::string(item.title);
    }
    app.add_option("--view", element, "A still of the islands framed on one element (implies --scene islands):" + list)
        ->transform(one_of(names))
        ->option_text("ELEMENT");
}
