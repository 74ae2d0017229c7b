#include "exporter.hpp"
#include "model_batch.hpp"

#include <raster/render/model_scene.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/obj_file.hpp>
#include <raster/io/reader_service.hpp>
#include <raster/io/texture_file.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <functional>
#include <future>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
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

// --background #RRGGBB: six hexadecimal digits, the # optional; or none.
bool is_hex_colour(const std::string& text) {
    const std::string digits = !text.empty() && text[0] == '#' ? text.substr(1) : text;
    return digits.size() == 6 && digits.find_first_not_of("0123456789abcdefABCDEF") == std::string::npos;
}

raster::Rgb colour_from_hex(const std::string& text) {
    const unsigned long value = std::stoul(text[0] == '#' ? text.substr(1) : text, nullptr, 16);
    return {static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value)};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    return text;
}

// A model read and made ready to draw, with what its reading found.
struct LoadedModel {
    std::shared_ptr<const raster::Model> model;
    std::vector<raster::InputRecord> inputs;  // every file read for it, which no output may replace
    std::vector<std::string> warnings;
    std::size_t triangles = 0;
    double seconds = 0.0;  // reading it took
    std::string refusal;  // why a batch will not draw it, though it was read
};

// What every model of a run shares: how to read it and how to look at it.
struct RenderPlan {
    raster::ObjOptions obj;
    std::shared_ptr<const raster::Texture> texture;  // --texture, read once
    std::string texture_path;
    std::vector<raster::InputRecord> texture_inputs;
    raster::TextureFilter filter = raster::TextureFilter::trilinear;
    raster::ModelView view;
    int frames = 0;  // 0: a still
    int fps = 30;
};

LoadedModel load_model(const std::string& path, const RenderPlan& plan) {
    const auto start = std::chrono::steady_clock::now();
    raster::Model model = raster::read_model(path, plan.obj);
    LoadedModel loaded;
    loaded.inputs = model.sources;
    loaded.inputs.insert(loaded.inputs.end(), plan.texture_inputs.begin(), plan.texture_inputs.end());
    loaded.warnings = model.warnings;
    if (plan.texture) {
        for (std::string& warning : raster::replace_diffuse_maps(model, plan.texture, plan.texture_path)) loaded.warnings.push_back(warning);
    }
    for (raster::ModelPart& part : model.parts) part.sampler.filter = plan.filter;
    loaded.triangles = raster::triangle_count(model);
    loaded.model = std::make_shared<const raster::Model>(std::move(model));
    loaded.seconds = seconds_since(start);
    return loaded;
}

// Draws one loaded model and returns the step that finishes it: a still's encoding, which may
// overlap the next model's drawing (an animation is written at once).
std::function<FinishedPicture()> render_model(const CLI::App& app, ExportOptions options, const LoadedModel& loaded,
                                              const RenderPlan& plan, raster::Renderer& renderer) {
    const auto start = std::chrono::steady_clock::now();
    options.inputs = loaded.inputs;
    if (!options.quiet) {
        for (const std::string& warning : loaded.warnings) std::cerr << app.get_name() << ": warning: " << warning << '\n';
    }
    const raster::ModelStage stage(loaded.model, plan.view, options.width, options.height);
    const auto draw = [&](raster::Framebuffer& frame, double turn, std::vector<std::uint8_t>& alpha) {
        stage.render(frame, renderer, turn);
        if (plan.view.transparent) alpha = renderer.coverage();
    };
    const std::string tail = ", " + std::to_string(loaded.triangles) + " triangles, ";
    const double loading = loaded.seconds;
    if (plan.frames == 0) {
        auto finish = render_still(app, options, [&](raster::Framebuffer& frame, std::vector<std::uint8_t>& alpha) { draw(frame, 0.0, alpha); });
        return [finish = std::move(finish), tail, loading, start] {
            FinishedPicture done = finish();
            done.report += tail + seconds_text(loading + seconds_since(start));
            return done;
        };
    }
    std::string report = export_animation(app, options, plan.frames, plan.fps, [&](raster::Framebuffer& frame, int index, std::vector<std::uint8_t>& alpha) {
        draw(frame, 2.0 * std::numbers::pi * index / plan.frames, alpha);
    });
    report += tail + seconds_text(loading + seconds_since(start));
    return [report] { return FinishedPicture{{}, report, true}; };
}

bool looks_like_a_model(const std::string& name) {
    std::string extension = std::filesystem::path(name).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* known : {".obj", ".gltf", ".glb", ".stl", ".ply"}) {
        if (extension == known) return true;
    }
    return false;
}

// Bytes from "512M", "2G", "2.5GiB", "1048576" (K, M, G, T are powers of 1024); nothing for other text.
std::optional<std::uint64_t> memory_size(const std::string& text) {
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    std::string unit(end);
    for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (unit.ends_with("IB")) unit.resize(unit.size() - 2);
    if (unit.ends_with("B")) unit.pop_back();
    static constexpr std::string_view kUnits = "KMGT";
    double bytes = number;
    if (unit.size() == 1 && kUnits.find(unit[0]) != std::string_view::npos) {
        bytes = std::ldexp(number, 10 * static_cast<int>(kUnits.find(unit[0]) + 1));
    } else if (!unit.empty()) {
        return std::nullopt;
    }
    if (end == text.c_str() || !std::isfinite(bytes) || bytes < 1.0 || bytes > 0x1p62) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Renders models (Wavefront OBJ with its MTL materials and textures, glTF 2.0 .gltf or .glb, "
                 "STL or PLY) to lossless WebP or PNG stills, or with --turntable to animations that turn them "
                 "once. Framed automatically; points and directions are in each model's own coordinates. "
                 "Several models at once need --output-dir.",
                 "render");
    app.footer("Examples:\n"
               "  render teapot.obj                        # -> teapot.webp, 800x600\n"
               "  render teapot.obj --turntable 120 spin.webp\n"
               "  render ship.obj --eye 4,2,6 --fov 30 --shading flat ship.webp\n"
               "  render crate.obj --texture wood.png --shading unlit crate.webp\n"
               "  render engine.glb --up 0,0,1 engine.webp   # a Z-up model\n"
               "  render part.stl --eye=-3,2,4 --background none part.png\n"
               "  render *.obj *.glb --width 256 --height 256 --output-dir thumbs\n"
               "  render vase.ply --turntable 90 --frames-dir frames   # frames/0000.png ...");
    std::string model_path;
    app.add_option("model", model_path,
                   "The model: .obj (its MTL files are looked for beside it, their textures relative to them), "
                   ".gltf (its buffers and images beside it), .glb, .stl or .ply")
        ->required()
        ->option_text("MODEL");
    ExportOptions options{"MODEL.webp (or .png with --format png), in the working directory"};
    add_export_options(app, options);
    add_samples_option(app, options, std::to_string(raster::kSmoothSamples));
    std::vector<std::string> more_models;
    app.add_option("more", more_models, "With --output-dir: more models, each drawn into DIR as its name with .webp or .png")
        ->option_text("MODEL...");
    std::string output_dir;
    auto* batch = app.add_option("--output-dir", output_dir,
                                 "Render every MODEL given into DIR (made if missing) as DIR/NAME.webp, or .png with --format png. "
                                 "The next model is read while one is drawn; a model that fails is reported and the rest "
                                 "are still written; the exit status is 1 if any failed")
                      ->option_text("DIR");
    batch->excludes(app.get_option("--output"));
    RenderPlan plan;
    raster::ModelView& view = plan.view;
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
    add_integer_option(app, "--turntable", plan.frames, 0, 10000,
                       "Write an animation of this many frames, 1..10000, turning the model once about --up");
    add_animation_options(app, plan.fps, options);
    batch->excludes(app.get_option("--frames-dir"));
    batch->excludes(app.get_option("--preview"));  // pictures made several at once: no one of them to show
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
    app.add_option("--background", background,
                   "Background colour, or none for a transparent one (alpha in WebP and PNG, so a thumbnail sits on any page; "
                   "a turntable then uses --encoder anim, which keeps alpha) [#30343c]")
        ->check(CLI::Validator([](std::string& text) {
                    return text == "none" || is_hex_colour(text) ? "" : "'" + raster::printable(text, 40) + "' is not a colour like #30343c, or none";
                }, ""))
        ->option_text("#RRGGBB|none");
    app.add_option("--texture", plan.texture_path, "Image (PNG, JPEG, TGA, BMP or WebP) to use as every material's diffuse map")
        ->option_text("FILE");
    add_choice_option<raster::TextureFilter>(app, "--filter", plan.filter,
                                             {{"nearest", raster::TextureFilter::nearest},
                                              {"bilinear", raster::TextureFilter::bilinear},
                                              {"trilinear", raster::TextureFilter::trilinear}},
                                             "Texture filtering (doc/lab/README.md#texture-filtering has the measurements)", "trilinear");
    app.add_option("--crease", plan.obj.crease_degrees,
                   "Normals the model lacks are smoothed across edges gentler than this angle and creased at sharper ones; 0 makes every facet flat [60]")
        ->check(finite_number(0.0, 180.0, false, " degrees"))
        ->option_text("DEGREES");
    std::string max_memory;
    app.add_option("--max-memory", max_memory,
                   "Memory one model's reading may take, as 512M, 2G or 2.5GiB: each model is read in a process of its own, and one "
                   "that needs more is refused in one line and the batch goes on [half the physical memory]")
        ->check(CLI::Validator([](std::string& text) { return memory_size(text) ? "" : "'" + raster::printable(text, 40) + "' is not a size like 512M or 2G"; }, ""))
        ->option_text("SIZE");
    app.add_option("--max-seconds", plan.obj.limits.max_seconds,
                   "Processor and wall-clock seconds one model's reading may take before it is stopped and refused [120]")
        ->check(finite_number(0.0, 1e6, true, " seconds"))
        ->option_text("SECONDS");
    std::string confine;
    app.add_option("--confine", confine,
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

    return run_exporter(app, options, argc, argv, [&] {
        const auto start = std::chrono::steady_clock::now();
        // Forked now, while the process is small: each model's reader is forked from it.
        const raster::ReaderService readers;
        plan.obj.limits.service = &readers;
        if (up) view.up = *up;
        view.light = light;
        if (background == "none") {
            view.transparent = options.transparent = true;
        } else if (!background.empty()) {
            view.background = colour_from_hex(background);
        }
        if (app.count("--confine") > 0) plan.obj.confine = raster::confinement_root(confine);
        if (!max_memory.empty()) plan.obj.limits.max_memory = *memory_size(max_memory);
        if (!options.frames_dir.empty() && plan.frames == 0) {
            throw CLI::ValidationError("--frames-dir writes the frames of a turntable; add --turntable N");
        }
        if (!options.frame_range.empty() && plan.frames == 0) {
            throw CLI::ValidationError("--frame-range picks frames of a turntable; add --turntable N");
        }
        if (options.skip_existing && plan.frames == 0 && output_dir.empty()) {
            throw CLI::ValidationError("--skip-existing keeps finished turntables and the pictures of --output-dir; a single still is simply drawn again");
        }
        if (!plan.texture_path.empty()) {
            plan.texture = std::make_shared<const raster::Texture>(
                raster::read_texture(plan.texture_path, raster::kMaxTextureTexels, plan.obj.confine, &plan.texture_inputs));
        }
        if (options.samples == 0) options.samples = raster::kSmoothSamples;
        raster::Renderer renderer(options.render_options());
        // Named outputs take their format from the name; made names from --format, else WebP.
        const bool named = output_dir.empty() && app.count("output") + app.count("--output") > 0;
        const ImageFormat format = named ? options.image_format() : options.format.value_or(ImageFormat::webp);
        const std::string extension = format == ImageFormat::png ? ".png" : ".webp";
        if (plan.frames > 0 && options.frames_dir.empty() && format == ImageFormat::png) {
            throw CLI::ValidationError("a PNG file holds one picture: write the turntable to .webp, or to numbered PNG frames "
                                       "with --frames-dir DIR");
        }
        if (output_dir.empty()) {
            if (!more_models.empty()) {
                throw CLI::ValidationError("several models need --output-dir DIR, for example: render a.obj b.glb --output-dir thumbs");
            }
            if (app.count("output") > 0 && looks_like_a_model(options.output)) {
                throw CLI::ValidationError("'" + raster::printable(options.output) +
                                           "' looks like a model, not a picture to write: give --output-dir DIR to render several "
                                           "models, or -o to write that name anyway");
            }
            if (!named) {
                options.output = std::filesystem::path(model_path).stem().string() + extension;
                options.format = format;
            }
            const LoadedModel loaded = load_model(model_path, plan);
            const FinishedPicture done = render_model(app, options, loaded, plan, renderer)();
            if (!done.written) {
                options.inputs = loaded.inputs;
                deliver(options, done.bytes);
            }
            return done.report;
        }
        std::vector<std::string> models{model_path};
        if (app.count("output") > 0) {
            if (!looks_like_a_model(options.output)) {
                throw CLI::ValidationError("'" + raster::printable(options.output) + "' is not a model (.obj, .gltf, .glb, .stl or .ply); "
                                           "with --output-dir, pictures are named after their models");
            }
            models.push_back(options.output);
        }
        models.insert(models.end(), more_models.begin(), more_models.end());
        std::vector<BatchJob> jobs = plan_batch(models, output_dir, extension);
        std::size_t kept = 0;
        if (options.skip_existing) {  // pictures are written atomically: one that decodes is whole
            kept = std::erase_if(jobs, [&](const BatchJob& job) { return holds_finished_picture(job.output, format); });
        }
        std::error_code error;
        std::filesystem::create_directories(output_dir, error);
        if (error || !std::filesystem::is_directory(output_dir)) {
            throw std::runtime_error("cannot make the output directory '" + raster::printable(output_dir) + "'" +
                                     (error ? ": " + error.message() : ": a file of that name is in the way"));
        }
        const auto report_failure = [&](const BatchJob& job, const std::string& reason) {
            const std::string model = raster::printable(job.model);
            std::cerr << app.get_name() << ": " << (reason.starts_with(model + ":") ? "" : model + ": ") << reason << '\n';
        };
        // Pictures are encoded on one thread per core at most while the next models are drawn
        // (encoding is most of a small model's time), and written between two reads, checked
        // against every file any model has read: no picture replaces another model's input.
        struct Encoding {
            const BatchJob* job;
            ExportOptions options;
            std::future<FinishedPicture> picture;
        };
        std::deque<Encoding> encoding, encoded;
        const auto in_flight = static_cast<std::size_t>(options.threads_in_use());
        std::vector<raster::InputRecord> every_input;
        std::vector<raster::FileIdentity> pictures;  // written so far
        std::size_t failed_writes = 0;
        // A file already at a picture's place may be what a later model reads: such pictures wait
        // until every model has been read (README: Rendering models you did not make).
        std::vector<HeldPicture> held;
        std::map<std::string, std::string> held_reports;  // by output
        std::vector<bool> existed(jobs.size());
        for (std::size_t i = 0; i < jobs.size(); ++i) {
            std::error_code missing;
            existed[i] = std::filesystem::exists(std::filesystem::symlink_status(jobs[i].output, missing));
        }
        const auto hold_if_existed = [&](const BatchJob& job, ExportOptions& one) {
            if (existed[static_cast<std::size_t>(&job - jobs.data())]) one.held = &held;
        };
        const auto write_encoded = [&] {
            for (Encoding& done : encoded) {
                try {
                    const FinishedPicture picture = done.picture.get();
                    done.options.inputs = every_input;
                    if (!picture.written) deliver(done.options, picture.bytes);
                    raster::FileIdentity identity;  // a held picture is not written yet: the file there is not ours
                    if (done.options.held == nullptr && raster::identity_of(done.options.output, identity)) pictures.push_back(identity);
                    if (done.options.held != nullptr) {
                        held_reports[done.options.output] = picture.report;  // said once it is written
                    } else if (!options.quiet) {
                        std::cout << picture.report << '\n' << std::flush;
                    }
                } catch (const std::exception& problem) {
                    report_failure(*done.job, problem.what());
                    ++failed_writes;
                }
            }
            encoded.clear();
        };
        const std::size_t drawn = run_prefetched<LoadedModel>(
            jobs, [&](const BatchJob& job) { return load_model(job.model, plan); },
            [&](const BatchJob& job, LoadedModel& loaded) {
                if (!loaded.refusal.empty()) throw std::runtime_error(loaded.refusal);
                ExportOptions one = options;
                one.output = job.output.string();
                one.show_progress = false;
                hold_if_existed(job, one);
                std::function<FinishedPicture()> finish = render_model(app, one, loaded, plan, renderer);
                while (encoding.size() >= in_flight) {  // wait for the oldest; it is written between reads
                    encoding.front().picture.wait();
                    encoded.push_back(std::move(encoding.front()));
                    encoding.pop_front();
                }
                encoding.push_back({&job, std::move(one), std::async(std::launch::async, std::move(finish))});
            },
            [&](LoadedModel* loaded) {
                if (loaded != nullptr) {  // what it read is known before anything more is written
                    for (const raster::InputRecord& input : loaded->inputs) {
                        if (std::find(pictures.begin(), pictures.end(), input.identity) != pictures.end()) {
                            loaded->refusal = "reads '" + raster::printable(input.path.string()) + "', a picture this run wrote";
                        }
                    }
                    every_input.insert(every_input.end(), loaded->inputs.begin(), loaded->inputs.end());
                }
                write_encoded();
            },
            report_failure);
        for (Encoding& last : encoding) encoded.push_back(std::move(last));
        write_encoded();
        for (HeldPicture& picture : held) {  // every model has been read: what each read is known
            picture.options.inputs = every_input;
            const auto job = std::find_if(jobs.begin(), jobs.end(), [&](const BatchJob& j) { return j.output.string() == picture.options.output; });
            try {
                deliver(picture.options, picture.bytes);
                if (!options.quiet) std::cout << held_reports[picture.options.output] << '\n' << std::flush;
            } catch (const std::exception& problem) {
                report_failure(*job, problem.what());
                ++failed_writes;
            }
        }
        const std::size_t written = drawn - failed_writes;
        const double seconds = seconds_since(start);
        const std::string summary = std::to_string(written) + " of " + std::to_string(jobs.size()) + " models into " +
                                    raster::printable(output_dir) + " in " + seconds_text(seconds) +
                                    (kept > 0 ? ", " + std::to_string(kept) + " already there kept" : "");
        if (written < jobs.size()) throw std::runtime_error("wrote " + summary + "; " + std::to_string(jobs.size() - written) + " failed");
        char rate[64];
        std::snprintf(rate, sizeof rate, " (%.1f a second)", static_cast<double>(written) / std::max(seconds, 1e-9));
        return "Rendered " + summary + rate;
    });
}
