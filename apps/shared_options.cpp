#include "shared_options.hpp"

#include "help_format.hpp"
#include "option_checks.hpp"

#include <raster/io/frame_range.hpp>
#include <raster/io/input_file.hpp>
#include <raster/render/samples.hpp>

#include <optional>
#include <utility>
#include <vector>

void add_output_options(CLI::App& app, ExportOptions& options) {
    const std::string output_help =
        "Picture to write: PNG for a name ending in .png or --format png, else WebP; replaced "
        "whole or not at all; - writes to standard output. Default: " +
        options.output;
    auto* positional = app.add_option("output", options.output, output_help)->option_text("FILE");
    auto* named = app.add_option("-o,--output", options.output, "The same, as an option")->option_text("FILE");
    positional->excludes(named);
    add_choice_option<std::optional<ImageFormat>>(app, "--format", options.format,
                                                  {{"webp", ImageFormat::webp}, {"png", ImageFormat::png}},
                                                  "File format: lossless WebP, or PNG (8-bit, for tools that want it). "
                                                  "Default: png for a name ending in .png, else webp",
                                                  "by name");
    add_choice_option<raster::Effort>(
        app, "--effort", options.effort,
        {{"fast", raster::Effort::fast}, {"default", raster::Effort::balanced}, {"max", raster::Effort::max}},
        "Lossless WebP compression effort: fast (quickest, largest file), default (small file), max "
        "(smallest, many times slower); PNG has one",
        "default");
    app.add_flag("-q,--quiet", options.quiet, "Print nothing when all goes well");
    app.add_flag("--progress", options.progress,
                 "Show progress on stderr even when it is not a terminal (it is shown on a terminal "
                 "anyway)");
    app.add_flag("--follow-symlinks", options.policy.follow_symlinks,
                 "If FILE is a symbolic link, replace the file it points to; without this, links, "
                 "FIFOs and devices are refused");
    app.add_flag("--preview", options.preview,
                 "Also show the picture (an animation's first frame) in the terminal, scaled to its "
                 "window, through the Kitty graphics protocol, which Kitty, WezTerm, Ghostty and Konsole "
                 "speak; the terminal is asked first, for up to a second. Elsewhere, or when standard "
                 "output is not a terminal, one line on stderr says why not. The file is written either "
                 "way; not with - as FILE, which takes standard output for the file");
}

void add_export_options(CLI::App& app, ExportOptions& options) {
    configure_app(app);
    const std::string side = "in pixels, 1.." + std::to_string(raster::kMaxImageSide) + " (the WebP limit)";
    add_integer_option(app, "--width", options.width, 1, raster::kMaxImageSide, "Image width " + side);
    add_integer_option(app, "--height", options.height, 1, raster::kMaxImageSide, "Image height " + side);
    add_integer_option(app, "--threads", options.threads, 0, 256,
                       "Threads for rendering (sharing each frame's vertices, facets and "
                       "strips of rows) and for encoding animation frames, 0..256; 0 (the "
                       "default) takes one per core, and so does a count above the cores, "
                       "since more would hold memory for no speed. The picture is the same "
                       "whatever the count");
    add_output_options(app, options);
}

void add_samples_option(CLI::App& app, ExportOptions& options, const std::string& default_text) {
    options.samples = 0;
    std::vector<std::pair<std::string, int>> counts;
    for (const int count : raster::kSampleCounts) counts.emplace_back(std::to_string(count), count);
    add_choice_option<int>(app, "--samples", options.samples, counts,
                           "Samples per pixel, for smooth edges: coverage and depth are tested at each of the "
                           "standard (Direct3D and Vulkan) sample positions, each pixel is shaded once, and its "
                           "samples are averaged in linear light. 1 draws each pixel at its centre, with "
                           "stair-step edges, and is the fastest",
                           default_text);
}

void add_style_option(CLI::App& app, raster::CubeStyle& style, const std::string& line_colour) {
    add_choice_option<raster::CubeStyle>(
        app, "--style", style,
        {{"filled", raster::CubeStyle::filled},
         {"wireframe", raster::CubeStyle::wireframe},
         {"culled-wireframe", raster::CubeStyle::culled_wireframe},
         {"lit", raster::CubeStyle::lit}},
        "filled: six flat-coloured faces; wireframe: all 12 edges in " + line_colour +
            "; culled-wireframe: only the edges of faces turned toward the camera; lit: one blue "
            "lit by a directional light (0.0.8)",
        "filled");
}

void add_animation_options(CLI::App& app, int& fps, ExportOptions& options) {
    // Browsers play frames of 10 ms or less at 100 ms, so the fastest honest rate gives 11 ms.
    constexpr int kMaxFps = 95;
    add_integer_option(app, "--fps", fps, 1, kMaxFps,
                       "Playback rate, 1..95. WebP stores whole milliseconds, so a frame lasts "
                       "round(1000 / fps) ms; browsers play frames of 10 ms or less at 100 ms, "
                       "so faster rates would play slower");
    add_choice_option<raster::AnimationPath>(
        app, "--encoder", options.encoder,
        {{"parallel", raster::AnimationPath::parallel}, {"anim", raster::AnimationPath::anim}},
        "parallel: each frame's changed rectangle encoded on every core while later frames render; anim: libwebp's "
        "own animation encoder, on one thread (doc/performance.md compares them)",
        "parallel");
    auto* frames_dir =
        app.add_option("--frames-dir", options.frames_dir,
                       "Write the frames as numbered PNG files (0000.png, 0001.png, ...) into DIR, made if "
                       "missing, instead of one animation: for video, e.g. ffmpeg -framerate 30 -i DIR/%04d.png "
                       "out.mp4")
            ->option_text("DIR");
    for (const char* output : {"output", "--output"}) {
        if (CLI::Option* named = app.get_option_no_throw(output)) frames_dir->excludes(named);
    }
    app.add_option(
           "--frame-range", options.frame_range,
           "Render only frames A to B (both included, counted from 0) of the whole clip, each exactly as the whole "
           "run renders it: into an animation marked as that part, for webp-assemble to join with the others, or "
           "with --frames-dir into their own numbered files. A..B or A:B")
        ->option_text("A..B")
        ->check([](const std::string& text) -> std::string {
            return raster::frame_range_from_text(text)
                       ? std::string()
                       : "'" + raster::printable(text) + "' is not A..B with 0 <= A <= B";
        });
    app.add_flag(
        "--skip-existing", options.skip_existing,
        "Leave an animation that is already complete (the same size and frames, or range) as it is and render "
        "nothing; with --frames-dir, render only the frames whose files are missing; with render --output-dir, "
        "only the models whose pictures are missing. Outputs are written "
        "atomically, so an interrupted run leaves no partial file to mistake for a finished one; a link, a "
        "directory, or a file that is empty or does not decode under the name is not taken as finished");
}
