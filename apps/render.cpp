#include "exporter.hpp"

#include <raster/model_scene.hpp>
#include <raster/model_file.hpp>
#include <raster/obj_file.hpp>
#include <raster/texture_file.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

// --eye 1,2,3 and the like: one word of three numbers separated by commas, so that the option
// takes exactly one argument wherever it stands and "-3,-3,-3" is a value, not an option.
std::string point_problem(const std::string& text, glm::dvec3& point) {
    std::size_t start = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t comma = text.find(',', start);
        if ((axis < 2) != (comma != std::string::npos)) return "'" + raster::printable(text, 40) + "' is not three numbers like 1,-2,3.5";
        if (std::string problem = read_finite(text.substr(start, comma - start), point[axis]); !problem.empty()) return problem;
        start = comma + 1;
    }
    return "";
}

void add_point_option(CLI::App& app, const std::string& name, std::optional<glm::dvec3>& point, const std::string& help) {
    app.add_option_function<std::string>(
           name,
           [&point](const std::string& text) {
               glm::dvec3 parsed(0.0);
               (void)point_problem(text, parsed);  // the check below has passed it
               point = parsed;
           },
           help)
        ->check(CLI::Validator(
            [](std::string& text) {
                glm::dvec3 parsed(0.0);
                return point_problem(text, parsed);
            },
            ""))
        ->option_text("X,Y,Z");
}

// --background #RRGGBB: six hexadecimal digits, the # optional.
bool is_hex_colour(const std::string& text) {
    const std::string digits = !text.empty() && text[0] == '#' ? text.substr(1) : text;
    return digits.size() == 6 && digits.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
}

raster::Rgb colour_from_hex(const std::string& text) {
    const unsigned long value = std::stoul(text[0] == '#' ? text.substr(1) : text, nullptr, 16);
    return {static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
}

std::string seconds_since(std::chrono::steady_clock::time_point start) {
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", elapsed.count());
    return text;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Renders a model (Wavefront OBJ with its MTL materials and textures, glTF 2.0 .gltf or .glb, "
                 "STL or PLY) to a lossless WebP still, or with --turntable to an animation that turns it "
                 "once. Framed automatically; "
                 "points and directions are in the model's own coordinates.",
                 "render");
    app.footer("Examples:\n"
               "  render teapot.obj                        # -> teapot.webp, 800x600\n"
               "  render teapot.obj --turntable 120 spin.webp\n"
               "  render ship.obj --eye 4,2,6 --fov 30 --shading flat ship.webp\n"
               "  render crate.obj --texture wood.png --shading unlit crate.webp\n"
               "  render engine.glb --up 0,0,1 engine.webp   # a Z-up model\n"
               "  render part.stl --eye=-3,2,4 part.webp");
    std::string model_path;
    app.add_option("model", model_path,
                   "The model: .obj (its MTL files are looked for beside it, their textures relative to them), "
                   ".gltf (its buffers and images beside it), .glb, .stl or .ply")
        ->required()
        ->option_text("MODEL");
    ExportOptions options{"MODEL.webp, in the working directory"};
    add_export_options(app, options);
    raster::ModelView view;
    add_point_option(app, "--eye", view.eye, "Where the camera stands. Default: in front, to the right and above, far enough back to see the whole model");
    add_point_option(app, "--target", view.target, "The point the camera looks at. Default: the middle of the model's bounding box");
    std::optional<glm::dvec3> up;
    add_point_option(app, "--up", up, "The direction that is up on screen, and the turntable's axis [0,1,0]");
    app.add_option("--fov", view.fov_degrees, "Vertical field of view in degrees, between 0 and 180 [40]")
        ->check(finite_number(0.0, 180.0, true, " degrees"))
        ->option_text("DEGREES");
    app.add_flag("--ortho", view.orthographic, "Orthographic projection: the bounding sphere fills the shorter side");
    app.add_option("--near", view.near, "Distance to the near clipping plane, in model units. Default: just short of the model")
        ->check(finite_number(0.0, HUGE_VAL, true))
        ->option_text("DISTANCE");
    app.add_option("--far", view.far, "Distance to the far clipping plane, in model units. Default: just beyond the model")
        ->check(finite_number(0.0, HUGE_VAL, true))
        ->option_text("DISTANCE");
    int frames = 0;
    add_integer_option(app, "--turntable", frames, 0, 10000,
                       "Write an animation of this many frames, 1..10000, turning the model once about --up");
    int fps = 30;
    add_animation_options(app, fps, options);
    add_choice_option<raster::ShadingMethod>(app, "--shading", view.shading,
                                             {{"flat", raster::ShadingMethod::flat},
                                              {"gouraud", raster::ShadingMethod::gouraud},
                                              {"phong", raster::ShadingMethod::phong},
                                              {"unlit", raster::ShadingMethod::unlit}},
                                             "Light per facet, per vertex or per pixel; unlit writes the material or texture colour "
                                             "with no light, for exact comparisons with other renderers",
                                             "phong");
    add_choice_option<raster::Culling>(app, "--cull", view.cull,
                                       {{"auto", raster::Culling::automatic}, {"back", raster::Culling::back}, {"none", raster::Culling::none}},
                                       "Which faces to draw: auto culls back faces only of a closed model and draws an open one (a plane, a "
                                       "leaf, a scan) from both sides; back always culls them; none draws both sides of everything",
                                       "auto");
    std::optional<glm::dvec3> light;
    add_point_option(app, "--light", light, "Direction toward the key light. Default: over the viewer's left shoulder; a dim fill comes from the other side");
    std::string background;
    app.add_option("--background", background, "Background colour [#30343c]")
        ->check(CLI::Validator([](std::string& text) { return is_hex_colour(text) ? "" : "'" + text + "' is not a colour like #30343c"; }, ""))
        ->option_text("#RRGGBB");
    std::string texture_path;
    app.add_option("--texture", texture_path, "Image (PNG, JPEG, TGA, BMP or WebP) to use as every material's diffuse map")
        ->option_text("FILE");
    raster::TextureFilter filter = raster::TextureFilter::trilinear;
    add_choice_option<raster::TextureFilter>(app, "--filter", filter,
                                             {{"nearest", raster::TextureFilter::nearest},
                                              {"bilinear", raster::TextureFilter::bilinear},
                                              {"trilinear", raster::TextureFilter::trilinear}},
                                             "Texture filtering (doc/lab/README.md#texture-filtering has the measurements)", "trilinear");
    raster::ObjOptions obj;
    app.add_option("--crease", obj.crease_degrees,
                   "Normals the model lacks are smoothed across edges gentler than this angle and creased at sharper ones; 0 makes every facet flat [60]")
        ->check(finite_number(0.0, 180.0, false, " degrees"))
        ->option_text("DEGREES");
    std::string confine;
    app.add_option("--confine", confine,
                   "Read nothing outside DIR (after resolving .. and symbolic links): the model must lie inside it, and "
                   "material libraries and textures the model names outside it are treated as missing, with a warning. "
                   "For models you did not make (README: Rendering models you did not make)")
        ->option_text("DIR");

    return run_exporter(app, options, argc, argv, [&] {
        const auto start = std::chrono::steady_clock::now();
        if (app.count("output") + app.count("--output") == 0) options.output = std::filesystem::path(model_path).stem().string() + ".webp";
        if (up) view.up = *up;
        view.light = light;
        if (!background.empty()) view.background = colour_from_hex(background);
        if (!confine.empty()) obj.confine = raster::confinement_root(confine);
        raster::Model model = raster::read_model(model_path, obj);
        options.inputs = model.sources;
        if (!texture_path.empty()) {
            const auto texture = std::make_shared<const raster::Texture>(
                raster::read_texture(texture_path, raster::kMaxTextureTexels, obj.confine, &options.inputs));
            for (std::string& warning : raster::replace_diffuse_maps(model, texture, texture_path)) model.warnings.push_back(warning);
        }
        for (raster::ModelPart& part : model.parts) part.sampler.filter = filter;
        if (!options.quiet) {
            for (const std::string& warning : model.warnings) std::cerr << "render: warning: " << warning << '\n';
        }
        const std::size_t triangles = raster::triangle_count(model);
        const raster::ModelStage stage(std::make_shared<const raster::Model>(std::move(model)), view, options.width, options.height);
        raster::Renderer renderer(options.render_options());
        std::string report;
        if (frames == 0) {
            report = export_still(app, options, [&](raster::Framebuffer& frame) { stage.render(frame, renderer, 0.0); });
        } else {
            report = export_animation(app, options, frames, fps, [&](raster::Framebuffer& frame, int index) {
                stage.render(frame, renderer, 2.0 * std::numbers::pi * index / frames);
            });
        }
        return report + ", " + std::to_string(triangles) + " triangles, " + seconds_since(start);
    });
}
