#include "render_options.hpp"

#include "option_checks.hpp"
#include "render_option_values.hpp"
#include "shared_options.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/texture_file.hpp>
#include <raster/render/samples.hpp>

#include <cmath>
#include <exception>
#include <memory>

std::string render_description() {
    return "Renders models (Wavefront OBJ with its MTL materials and textures, glTF 2.0 .gltf or .glb, "
           "STL, PLY, and the formats of the Open Asset Import Library: Collada, FBX, 3DS, OFF, 3MF, ...) to lossless WebP or PNG stills, or with --turntable to animations that turn them "
           "once. Framed automatically; points and directions are in each model's own coordinates. "
           "Several models at once need --output-dir.";
}

void add_render_options(CLI::App& app, RenderArguments& arguments) {
    ExportOptions& options = arguments.options;
    RenderPlan& plan = arguments.plan;
    raster::ModelView& view = plan.view;
    app.footer("Examples:\n"
               "  render teapot.obj                        # -> teapot.webp, 800x600\n"
               "  render teapot.obj --turntable 120 spin.webp\n"
               "  render ship.obj --eye 4,2,6 --fov 30 --shading flat ship.webp\n"
               "  render crate.obj --texture wood.png --shading unlit crate.webp\n"
               "  render engine.glb --up 0,0,1 engine.webp   # a Z-up model\n"
               "  render part.stl --eye=-3,2,4 --background none part.png\n"
               "  render *.obj *.glb --width 256 --height 256 --output-dir thumbs\n"
               "  render vase.ply --turntable 90 --frames-dir frames   # frames/0000.png ...");
    app.add_option("model", arguments.model_path,
                   "The model: .obj (its MTL files are looked for beside it, their textures relative to them), "
                   ".gltf (its buffers and images beside it), .glb, .stl, .ply, or one of " +
                       raster::model_endings().substr(std::string_view(".obj, .gltf, .glb, .stl, .ply, ").size()))
        ->required()
        ->option_text("MODEL");
    add_export_options(app, options);
    add_samples_option(app, options, std::to_string(raster::kSmoothSamples));
    app.add_option("more", arguments.more_models,
                   "With --output-dir: more models, each drawn into DIR as its name with .webp or .png")
        ->option_text("MODEL...");
    auto* batch =
        app.add_option(
               "--output-dir", arguments.output_dir,
               "Render every MODEL given into DIR (made if missing) as DIR/NAME.webp, or .png with --format png. "
               "The next model is read while one is drawn; a model that fails is reported and the rest "
               "are still written; the exit status is 1 if any failed")
            ->option_text("DIR");
    batch->excludes(app.get_option("--output"));
    add_point_option(
        app, "--eye", view.eye,
        "Where the camera stands. Default: in front, to the right and above, far enough back to see the whole model");
    add_point_option(app, "--target", view.target,
                     "The point the camera looks at. Default: the middle of the model's bounding box");
    add_point_option(app, "--up", arguments.up, "The direction that is up on screen, and the turntable's axis [0,1,0]");
    app.add_option("--fov", view.fov_degrees, "Vertical field of view in degrees, between 0 and 180 [40]")
        ->check(finite_number(0.0, 180.0, true, " degrees"))
        ->option_text("DEGREES");
    app.add_flag("--ortho", view.orthographic, "Orthographic projection: the bounding sphere fills the shorter side");
    app.add_option("--near", view.near,
                   "Distance to the near clipping plane, in model units. Default: just short of the model")
        ->check(finite_number(0.0, HUGE_VAL, true))
        ->option_text("DISTANCE");
    app.add_option("--far", view.far,
                   "Distance to the far clipping plane, in model units. Default: just beyond the model")
        ->check(finite_number(0.0, HUGE_VAL, true))
        ->option_text("DISTANCE");
    app.add_option("--point-size", view.points_and_lines.point_size,
                   "Diameter of each point (a point cloud, OBJ p, PLY vertices without faces, glTF POINTS), in pixels, "
                   "1 to 64. Default: from the points' density on screen, so that a scan reads as a surface")
        ->check(finite_number(raster::kMinPointSize, raster::kMaxPointSize, false, " pixels"))
        ->option_text("PX");
    app.add_option("--line-width", view.points_and_lines.line_width,
                   "Width of each line (OBJ l, glTF LINES and strips), in pixels, 0.5 to 64; anti-aliased by "
                   "--samples [1.5]")
        ->check(finite_number(raster::kMinLineWidth, raster::kMaxLineWidth, false, " pixels"))
        ->option_text("PX");
    auto* camera = add_integer_option(
        app, "--camera", plan.camera, 0, 1000000,
        "Draw from the model file's camera N (0 is the first; glTF's cameras, placed by their nodes) instead of "
        "raster's own framing: its place, direction, field of view (or orthographic height) and clipping planes");
    camera->option_text("N");  // the default is raster's framing, not a camera
    for (const char* framing : {"--eye", "--target", "--fov", "--ortho", "--near", "--far"})
        camera->excludes(app.get_option(framing));
    add_integer_option(app, "--turntable", plan.frames, 0, 10000,
                       "Write an animation of this many frames, 1..10000, turning the model once about --up");
    add_animation_options(app, plan.fps, options);
    batch->excludes(app.get_option("--frames-dir"));
    batch->excludes(app.get_option("--preview"));  // pictures made several at once: no one of them to show
    add_choice_option<raster::ShadingMethod>(
        app, "--shading", view.shading,
        {{"flat", raster::ShadingMethod::flat},
         {"gouraud", raster::ShadingMethod::gouraud},
         {"phong", raster::ShadingMethod::phong},
         {"unlit", raster::ShadingMethod::unlit}},
        "Light per facet, per vertex or per pixel; unlit writes the material or texture colour "
        "with no light, for exact comparisons with other renderers",
        "phong");
    add_choice_option<raster::Culling>(
        app, "--cull", view.cull,
        {{"auto", raster::Culling::automatic}, {"back", raster::Culling::back}, {"none", raster::Culling::none}},
        "Which faces to draw: auto culls back faces only of a closed model and draws an open one (a plane, a "
        "leaf, a scan) from both sides; back always culls them; none draws both sides of everything",
        "auto");
    add_point_option(
        app, "--light", arguments.light,
        "Direction toward the key light. Default: over the viewer's left shoulder; a dim fill comes from the other side");
    app.add_option(
           "--background", arguments.background,
           "Background colour, or none for a transparent one (alpha in WebP and PNG, so a thumbnail sits on any page; "
           "a turntable then uses --encoder anim, which keeps alpha) [#30343c]")
        ->check(CLI::Validator(
            [](std::string& text) {
                return text == "none" || is_hex_colour(text)
                           ? ""
                           : "'" + raster::printable(text, 40) + "' is not a colour like #30343c, or none";
            },
            ""))
        ->option_text("#RRGGBB|none");
    app.add_option("--texture", plan.texture_path,
                   "Image (PNG, JPEG, TGA, BMP or WebP) to use as every material's diffuse map")
        ->option_text("FILE");
    add_choice_option<raster::TextureFilter>(
        app, "--filter", plan.filter,
        {{"nearest", raster::TextureFilter::nearest},
         {"bilinear", raster::TextureFilter::bilinear},
         {"trilinear", raster::TextureFilter::trilinear}},
        "Texture filtering (doc/lab/README.md#texture-filtering has the measurements)", "trilinear");
    app.add_option(
           "--crease", plan.obj.crease_degrees,
           "Normals the model lacks are smoothed across edges gentler than this angle and creased at sharper ones; 0 makes every facet flat [60]")
        ->check(finite_number(0.0, 180.0, false, " degrees"))
        ->option_text("DEGREES");
    app.add_option(
           "--max-memory", arguments.max_memory,
           "Memory one model's reading may take, as 512M, 2G or 2.5GiB: a model read through assimp or tinyobjloader is "
           "read in a process of its own, a PLY or STL (raster's own readers) here with its counts checked first; one "
           "that needs more is refused in one line and the batch goes on [half the physical memory]")
        ->check(CLI::Validator(
            [](std::string& text) {
                return memory_size(text) ? "" : "'" + raster::printable(text, 40) + "' is not a size like 512M or 2G";
            },
            ""))
        ->option_text("SIZE");
    app.add_option(
           "--max-seconds", plan.obj.limits.max_seconds,
           "Processor and wall-clock seconds one model's reading may take before it is stopped and refused [120]")
        ->check(finite_number(0.0, 1e6, true, " seconds"))
        ->option_text("SECONDS");
    app.add_option(
           "--confine", arguments.confine,
           "Read nothing outside DIR (after resolving .. and symbolic links): the model must lie inside it, and "
           "material libraries and textures the model names outside it are treated as missing, with a warning. "
           "For models you did not make (README: Rendering models you did not make)")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                // An empty name would confine nothing, silently.
                if (text.empty()) return "needs a directory; an empty name confines nothing";
                try {
                    (void)raster::confinement_root(text);
                } catch (const std::exception& problem) {
                    return problem.what();
                }
                return "";
            },
            ""))
        ->option_text("DIR");
    app.add_flag(
        "--timings", plan.timings,
        "After the report, print on standard error each stage's wall and processor (user + system) seconds, "
        "summed over a turntable's frames: read (the model: here for PLY and STL, else in its child process and the copy back), "
        "prepare (framing, staging, each frame's scene), draw, resolve (of the samples) and encode (and "
        "write; a turntable's frames are encoded while the next are drawn, so its encode is the rest of the "
        "export). 'one core' is the share of the wall time with at most one thread busy: counted for draw "
        "and resolve, which run on the worker threads; estimated (~) for the others as (T*W - C)/((T-1)*W) "
        "from the wall W and processor time C on T threads, which holds only for a stage that runs either "
        "on one thread or on all. A high share is the serial part that more cores will not speed up "
        "(doc/performance.md#stage-timings)");
}

void settle_arguments(const CLI::App& app, RenderArguments& arguments, const raster::ReaderService& readers) {
    ExportOptions& options = arguments.options;
    RenderPlan& plan = arguments.plan;
    raster::ModelView& view = plan.view;
    plan.obj.limits.service = &readers;
    plan.obj.threads = static_cast<std::size_t>(options.threads_in_use());
    if (arguments.up) view.up = *arguments.up;
    view.light = arguments.light;
    if (arguments.background == "none") {
        view.transparent = options.transparent = true;
    } else if (!arguments.background.empty()) {
        view.background = colour_from_hex(arguments.background);
    }
    if (app.count("--confine") > 0) plan.obj.confine = raster::confinement_root(arguments.confine);
    if (!arguments.max_memory.empty()) plan.obj.limits.max_memory = *memory_size(arguments.max_memory);
    if (!options.frames_dir.empty() && plan.frames == 0) {
        throw CLI::ValidationError("--frames-dir writes the frames of a turntable; add --turntable N");
    }
    if (!options.frame_range.empty() && plan.frames == 0) {
        throw CLI::ValidationError("--frame-range picks frames of a turntable; add --turntable N");
    }
    if (options.skip_existing && plan.frames == 0 && arguments.output_dir.empty()) {
        throw CLI::ValidationError(
            "--skip-existing keeps finished turntables and the pictures of --output-dir; a single still is simply drawn again");
    }
    if (plan.timings && !arguments.output_dir.empty()) {
        throw CLI::ValidationError(
            "--timings times the stages of one model's job; a batch (--output-dir) overlaps them, so time one model");
    }
    if (!plan.texture_path.empty()) {
        plan.texture = std::make_shared<const raster::Texture>(
            raster::read_texture(plan.texture_path, raster::kMaxTextureTexels, plan.obj.confine, &plan.texture_inputs));
    }
    if (options.samples == 0) options.samples = raster::kSmoothSamples;
}
