#include "exporter.hpp"
#include "terminal_preview.hpp"

#include <raster/io/png.hpp>
#include <raster/io/input_file.hpp>
#include <raster/version.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <sched.h>
#include <thread>
#include <unistd.h>

namespace {

constexpr std::size_t kHelpWidth = 80;
constexpr std::size_t kOptionColumn = 30;

// Breaks lines longer than `width` at spaces; shorter lines, such as examples, stay as written.
std::string wrap(const std::string& text, std::size_t width) {
    std::string wrapped;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (!wrapped.empty()) wrapped += '\n';
        while (line.size() > width) {
            const std::size_t space = line.rfind(' ', width);
            if (space == std::string::npos || space == 0) break;
            wrapped += line.substr(0, space) + '\n';
            line.erase(0, space + 1);
        }
        wrapped += line;
    }
    return wrapped;
}

class WrappingFormatter : public CLI::Formatter {
public:
    std::string make_option_desc(const CLI::Option* option) const override {
        return wrap(option->get_description(), kHelpWidth - get_column_width());
    }
    std::string make_description(const CLI::App* app) const override {
        const std::string text = app->get_description();
        return text.empty() ? "" : wrap(text, kHelpWidth) + "\n\n";
    }
    std::string make_footer(const CLI::App* app) const override {
        const std::string text = app->get_footer();
        return text.empty() ? "" : wrap(text, kHelpWidth) + "\n";
    }
};

bool is_terminal(int descriptor) { return ::isatty(descriptor) == 1; }

std::string lowered_extension(const std::string& name) {
    std::string extension = std::filesystem::path(name).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

ImageFormat ExportOptions::image_format() const {
    if (format) return *format;
    return lowered_extension(output) == ".png" ? ImageFormat::png : ImageFormat::webp;
}

int ExportOptions::threads_in_use() const {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    const int cores = ::sched_getaffinity(0, sizeof allowed, &allowed) == 0 ? CPU_COUNT(&allowed)
                                                                            : static_cast<int>(std::thread::hardware_concurrency());
    return threads == 0 ? std::max(cores, 1) : std::min(threads, std::max(cores, 1));
}

void configure_app(CLI::App& app) {
    auto formatter = std::make_shared<WrappingFormatter>();
    formatter->column_width(kOptionColumn);
    app.formatter(formatter);
    app.set_version_flag("--version", app.get_name() + " " + raster::kVersion + " (raster)",
                         "Print the program's name and version, then exit");
    app.set_help_flag("-h,--help", "Print this help, then exit");
}

CLI::Option* add_integer_option(CLI::App& app, const std::string& name, int& value, int low, int high,
                                const std::string& help) {
    const std::string range = std::to_string(low) + ".." + std::to_string(high);
    const CLI::Validator decimal_in_range(
        [low, high, range](std::string& given) -> std::string {
            long long parsed = 0;
            const char* end = given.data() + given.size();
            const auto [stop, error] = std::from_chars(given.data(), end, parsed, 10);
            if (given.empty() || stop != end || (error != std::errc() && error != std::errc::result_out_of_range)) {
                return "'" + given + "' is not an integer (expected a decimal number " + range + ")";
            }
            if (error == std::errc::result_out_of_range || parsed < low || parsed > high) {
                return given + " is out of range (expected " + range + ")";
            }
            given = std::to_string(parsed);  // CLI11 would read a leading 0 as octal
            return {};
        },
        "", "decimal " + range);
    return app.add_option(name, value, help)
        ->transform(decimal_in_range)
        ->option_text("N [" + std::to_string(value) + "]");
}

std::string read_finite(const std::string& given, double& value) {
    std::string_view digits = given;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const std::string quoted = "'" + raster::printable(given, 40) + "'";
    if (digits.empty() || end != digits.data() + digits.size() || (error != std::errc() && error != std::errc::result_out_of_range)) {
        return quoted + " is not a number";
    }
    if (error == std::errc::result_out_of_range) {
        const std::string copy(digits);
        value = std::strtod(copy.c_str(), nullptr);  // tells overflow (huge) from underflow (tiny, as good as 0)
    }
    return std::isfinite(value) ? "" : "must be finite, not " + quoted;
}

CLI::Validator finite_number(double low, double high, bool open_ends, const std::string& unit) {
    const auto shown = [](double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", value);
        return std::string(text);
    };
    std::string range;
    if (low == 0.0 && std::isinf(high)) {
        range = open_ends ? "must be positive" : "must not be negative";
    } else if (!std::isinf(low) || !std::isinf(high)) {
        range = "must be " + std::string(open_ends ? "strictly " : "") + "between " + shown(low) + " and " + shown(high) + unit;
    }
    return {[=](std::string& given) -> std::string {
                double value = 0.0;
                if (std::string problem = read_finite(given, value); !problem.empty()) return problem;
                const bool inside = open_ends ? value > low && value < high : value >= low && value <= high;
                return inside ? std::string() : range + ", not '" + raster::printable(given, 40) + "'";
            },
            "", ""};
}

CLI::Validator one_of(const std::vector<std::string>& names) {
    const std::string listed = CLI::detail::join(names, ", ");
    return {[names, listed](std::string& given) -> std::string {
                std::string lowered = given;
                std::transform(lowered.begin(), lowered.end(), lowered.begin(),
                               [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
                if (std::find(names.begin(), names.end(), lowered) == names.end()) {
                    return "'" + given + "' is not one of " + listed;
                }
                given = lowered;
                return {};
            },
            "", "one of " + listed};
}

void add_output_options(CLI::App& app, ExportOptions& options) {
    const std::string output_help = "Picture to write: PNG for a name ending in .png or --format png, else WebP; replaced "
                                    "whole or not at all; - writes to standard output. Default: " + options.output;
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

Progress::Progress(std::string program, const ExportOptions& options)
    : program_(std::move(program)), enabled_(options.show_progress && (options.progress || (!options.quiet && is_terminal(2)))),
      terminal_(is_terminal(2)) {}

Progress::~Progress() {
    if (line_open_) std::cerr << "\r\033[K" << std::flush;  // leave the terminal as it was
}

void Progress::frame(int done, int total) {
    if (!enabled_) return;
    if (terminal_) {
        show("frame " + std::to_string(done) + "/" + std::to_string(total));
        return;
    }
    const int tenth = done * 10 / std::max(total, 1);  // a log gets a line per tenth
    if (tenth != last_tenth_) {
        last_tenth_ = tenth;
        show("frame " + std::to_string(done) + "/" + std::to_string(total));
    }
}

void Progress::stage(const std::string& what) {
    if (enabled_) show(what);
}

void Progress::pause() {
    if (line_open_) std::cerr << "\r\033[K" << std::flush;
    line_open_ = false;
}

void Progress::show(const std::string& text) {
    if (terminal_) {
        std::cerr << "\r\033[K" << program_ << ": " << text << std::flush;
        line_open_ = true;
    } else {
        std::cerr << program_ << ": " << text << '\n' << std::flush;
    }
}

void check_output(const CLI::App& app, const ExportOptions& options) {
    if (options.output == "-" && options.preview) {
        throw CLI::ValidationError("--preview shows the picture on standard output, which - takes for the file; name a file to write");
    }
    if (options.output == "-") {
        if (is_terminal(1)) {
            throw std::runtime_error("standard output is a terminal; redirect it to a file or a pipe");
        }
        return;
    }
    raster::check_output_path(options.output, options.policy, options.inputs);
    const bool png = options.image_format() == ImageFormat::png;
    if (lowered_extension(options.output) != (png ? ".png" : ".webp") && !options.quiet) {
        std::cerr << app.get_name() << ": warning: '" << raster::printable(options.output) << "' does not end in "
                  << (png ? ".png, but it will hold PNG data\n" : ".webp, but it will hold WebP data\n");
    }
}

void preview(const CLI::App& app, const ExportOptions& options, const raster::Framebuffer& image, std::span<const std::uint8_t> alpha) {
    if (!options.preview) return;
    const std::string why_not = show_on_terminal(image, alpha);
    if (!why_not.empty() && !options.quiet) std::cerr << app.get_name() << ": no preview: " << why_not << '\n' << std::flush;
}

void deliver(const ExportOptions& options, std::span<const std::uint8_t> bytes) {
    if (options.held != nullptr) {
        options.held->push_back({options, {bytes.begin(), bytes.end()}});
        options.held->back().options.held = nullptr;
        return;
    }
    if (options.output != "-") {
        raster::write_output_file(options.output, bytes, options.policy, options.inputs);
        return;
    }
    while (!bytes.empty()) {
        const ::ssize_t written = ::write(1, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            throw std::runtime_error(std::string("cannot write to standard output: ") +
                                     std::strerror(written < 0 ? errno : EIO));
        }
        bytes = bytes.subspan(static_cast<std::size_t>(written));
    }
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
        std::cerr << app.get_name() << ": " << error.what() << " (see --help)\n";
        return 2;
    }
    return std::nullopt;
}

int run_exporter(CLI::App& app, const ExportOptions& options, int argc, char** argv,
                 const std::function<std::string()>& export_file) {
    if (const std::optional<int> exit_code = parse_command_line(app, argc, argv)) return *exit_code;
    try {
        const std::string report = export_file();
        std::ostream& out = options.output == "-" ? std::cerr : std::cout;
        if (!options.quiet && !(out << report << '\n' << std::flush)) return 1;  // e.g. a closed stdout
        return 0;
    } catch (const CLI::ParseError& error) {  // options that clash in a way only the run can see
        std::cerr << app.get_name() << ": " << error.what() << " (see --help)\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << app.get_name() << ": " << error.what() << '\n';
        return 1;
    }
}

namespace {

std::string describe_destination(const ExportOptions& options) {
    return options.output == "-" ? "Wrote standard output" : "Wrote " + raster::printable(options.output);
}

}  // namespace

std::function<FinishedPicture()> render_still(const CLI::App& app, const ExportOptions& options, const RenderStill& render) {
    check_output(app, options);
    auto progress = std::make_shared<Progress>(app.get_name(), options);
    progress->stage("rendering");
    auto frame = std::make_shared<raster::Framebuffer>(options.width, options.height);
    auto alpha = std::make_shared<std::vector<std::uint8_t>>();
    render(*frame, *alpha);
    progress->pause();
    preview(app, options, *frame, *alpha);
    return [options, progress, frame, alpha] {
        progress->stage("encoding");
        const std::vector<std::uint8_t> bytes = options.image_format() == ImageFormat::png
                                                    ? raster::encode_png(*frame, *alpha)
                                                    : raster::encode_webp_still(*frame, options.effort, *alpha);
        std::string report = describe_destination(options) + ": " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                             (alpha->empty() ? " still, " : " still on a transparent background, ") + std::to_string(bytes.size()) + " bytes";
        return FinishedPicture{bytes, std::move(report)};
    };
}

std::string export_still(const CLI::App& app, const ExportOptions& options, const RenderStill& render) {
    const FinishedPicture done = render_still(app, options, render)();
    deliver(options, done.bytes);
    return done.report;
}

std::string export_still(const CLI::App& app, const ExportOptions& options, const std::function<void(raster::Framebuffer&)>& render) {
    return export_still(app, options, [&](raster::Framebuffer& frame, std::vector<std::uint8_t>&) { render(frame); });
}

bool parse_frame_range(const std::string& text, int& first, int& last) {
    const std::size_t dots = text.find(".."), colon = text.find(':');
    const std::size_t split = dots != std::string::npos ? dots : colon;
    if (split == std::string::npos) return false;
    const std::string_view a(text.data(), split), b(text.data() + split + (dots != std::string::npos ? 2 : 1));
    const auto read = [](std::string_view digits, int& value) {
        if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) return false;
        return std::from_chars(digits.data(), digits.data() + digits.size(), value).ec == std::errc();
    };
    return read(a, first) && read(b, last) && first <= last;
}

void add_animation_options(CLI::App& app, int& fps, ExportOptions& options) {
    // Browsers play frames of 10 ms or less at 100 ms, so the fastest honest rate gives 11 ms.
    constexpr int kMaxFps = 95;
    add_integer_option(app, "--fps", fps, 1, kMaxFps,
                       "Playback rate, 1..95. WebP stores whole milliseconds, so a frame lasts "
                       "round(1000 / fps) ms; browsers play frames of 10 ms or less at 100 ms, "
                       "so faster rates would play slower");
    add_choice_option<raster::AnimationPath>(
        app, "--encoder", options.encoder, {{"parallel", raster::AnimationPath::parallel}, {"anim", raster::AnimationPath::anim}},
        "parallel: each frame's changed rectangle encoded on every core while later frames render; anim: libwebp's "
        "own animation encoder, on one thread (doc/performance.md compares them)",
        "parallel");
    auto* frames_dir = app.add_option("--frames-dir", options.frames_dir,
                                      "Write the frames as numbered PNG files (0000.png, 0001.png, ...) into DIR, made if "
                                      "missing, instead of one animation: for video, e.g. ffmpeg -framerate 30 -i DIR/%04d.png "
                                      "out.mp4")
                           ->option_text("DIR");
    for (const char* output : {"output", "--output"}) {
        if (CLI::Option* named = app.get_option_no_throw(output)) frames_dir->excludes(named);
    }
    app.add_option("--frame-range", options.frame_range,
                   "Render only frames A to B (both included, counted from 0) of the whole clip, each exactly as the whole "
                   "run renders it: into an animation marked as that part, for webp-assemble to join with the others, or "
                   "with --frames-dir into their own numbered files. A..B or A:B")
        ->option_text("A..B")
        ->check([](const std::string& text) -> std::string {
            int first = 0, last = 0;
            return parse_frame_range(text, first, last) ? std::string() : "'" + raster::printable(text) + "' is not A..B with 0 <= A <= B";
        });
    app.add_flag("--skip-existing", options.skip_existing,
                 "Leave an animation that is already complete (the same size and frames, or range) as it is and render "
                 "nothing; with --frames-dir, render only the frames whose files are missing; with render --output-dir, "
                 "only the models whose pictures are missing. Outputs are written "
                 "atomically, so an interrupted run leaves no partial file to mistake for a finished one; a link, a "
                 "directory, or a file that is empty or does not decode under the name is not taken as finished");
}

namespace {

// Frame i's file: at least four digits, as many as the last frame's number needs.
std::filesystem::path frame_file(const std::filesystem::path& dir, int index, int frames) {
    const int digits = std::max(4, static_cast<int>(std::to_string(std::max(frames - 1, 0)).size()));
    std::string number = std::to_string(index);
    number.insert(0, static_cast<std::size_t>(std::max(0, digits - static_cast<int>(number.size()))), '0');
    return dir / (number + ".png");
}

// The frames to render: all of them, or --frame-range checked against the clip's length.
std::optional<raster::FrameRange> chosen_range(const ExportOptions& options, int frames, int fps) {
    int first = 0, last = 0;
    if (options.frame_range.empty() || !parse_frame_range(options.frame_range, first, last)) return std::nullopt;
    if (last >= frames) {
        throw std::runtime_error("--frame-range " + options.frame_range + " goes past the clip's last frame, " + std::to_string(frames - 1));
    }
    return raster::FrameRange{first, last, frames, (1000 + fps / 2) / fps};
}

std::string range_text(const raster::FrameRange& range) {
    return "frames " + std::to_string(range.first) + ".." + std::to_string(range.last) + " of " + std::to_string(range.total);
}

// Whether the output already holds what this run would write: this range (or none, for a
// whole clip), this size and frame timing, and this run's first frame, drawn to compare.
bool already_complete(const ExportOptions& options, const std::optional<raster::FrameRange>& range, int count, int spacing_ms,
                      const raster::Framebuffer& first) {
    const std::filesystem::path path = options.output;
    try {
        const std::vector<std::uint8_t> bytes = raster::read_input_file(
            path, raster::InputRules{"animation", raster::kMaxWebpFileBytes, raster::looks_like_webp, 12, "a WebP file", {}});
        if (raster::frame_range_of(bytes) != range) return false;
        bool same_first = false;
        std::int64_t lasts_ms = 0;
        int frames = 0;
        const raster::WebpInfo info = raster::for_each_webp_frame(path, [&](const raster::DecodedFrame& frame) {
            if (frames++ == 0) same_first = frame.image == first;
            // libwebp's own encoder lengthens a frame instead of repeating it, down to a still (no duration).
            const int lasts = frame.duration_ms > 0 ? frame.duration_ms : count * spacing_ms;
            lasts_ms += lasts;
            return same_first && lasts % spacing_ms == 0;
        });
        return same_first && info.width == options.width && info.height == options.height && lasts_ms == std::int64_t{count} * spacing_ms;
    } catch (const std::exception&) {
        return false;
    }
}

std::string export_frames(const CLI::App& app, const ExportOptions& options, int frames, int fps, const RenderFrame& render) {
    const std::filesystem::path dir = options.frames_dir;
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error || !std::filesystem::is_directory(dir)) {
        throw std::runtime_error("cannot make the frames directory '" + raster::printable(dir.string()) + "'" +
                                 (error ? ": " + error.message() : ": a file of that name is in the way"));
    }
    const std::optional<raster::FrameRange> range = chosen_range(options, frames, fps);
    const int begin = range ? range->first : 0, end = range ? range->last + 1 : frames;
    // Files are written atomically, so a PNG file that decodes is a whole frame from an earlier run.
    std::vector<bool> kept_frames(static_cast<std::size_t>(end - begin));
    for (int i = begin; i < end; ++i) {
        kept_frames[static_cast<std::size_t>(i - begin)] = options.skip_existing && holds_finished_picture(frame_file(dir, i, frames), ImageFormat::png);
    }
    const auto skipped = [&](int i) { return kept_frames[static_cast<std::size_t>(i - begin)]; };
    for (int i = begin; i < end; ++i) {
        if (!skipped(i)) raster::check_output_path(frame_file(dir, i, frames), options.policy, options.inputs);
    }
    raster::Framebuffer frame(options.width, options.height);
    Progress progress(app.get_name(), options);
    std::uintmax_t total = 0;
    int written = 0;
    std::vector<std::uint8_t> alpha;
    for (int i = begin; i < end; ++i) {
        if (skipped(i)) continue;
        alpha.clear();
        render(frame, i, alpha);
        if (written == 0) preview(app, options, frame, alpha);
        const std::vector<std::uint8_t> bytes = raster::encode_png(frame, alpha);
        raster::write_output_file(frame_file(dir, i, frames), bytes, options.policy, options.inputs);
        total += bytes.size();
        ++written;
        progress.frame(i - begin + 1, end - begin);
    }
    const int kept = end - begin - written;
    return "Wrote " + raster::printable(frame_file(dir, begin, frames).string()) + " to " +
           frame_file(dir, end - 1, frames).filename().string() + ": " + std::to_string(written) + " PNG frames of " +
           std::to_string(options.width) + "x" + std::to_string(options.height) + " for " + std::to_string(fps) + " fps, " +
           std::to_string(total) + " bytes" + (kept > 0 ? ", " + std::to_string(kept) + " already there kept" : "") +
           (range ? ", " + range_text(*range) : "");
}

}  // namespace

std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps, const RenderFrame& render) {
    if (!options.frames_dir.empty()) return export_frames(app, options, frames, fps, render);
    if (options.image_format() == ImageFormat::png) {
        throw std::runtime_error("a PNG file holds one picture: write the animation to a .webp file, or to numbered PNG "
                                 "frames with --frames-dir DIR");
    }
    const std::optional<raster::FrameRange> range = chosen_range(options, frames, fps);
    const int begin = range ? range->first : 0, end = range ? range->last + 1 : frames;
    const int spacing_ms = (1000 + fps / 2) / fps;
    raster::Framebuffer frame(options.width, options.height);
    std::vector<std::uint8_t> alpha;
    // already_complete() decodes the file, so only what cannot be a finished one is ruled out here.
    const bool drawn_first = options.skip_existing && options.output != "-" && is_nonempty_regular_file(options.output);
    if (drawn_first) {
        render(frame, begin, alpha);
        if (already_complete(options, range, end - begin, spacing_ms, frame)) {
            return "Skipped " + raster::printable(options.output) + ": it already holds " +
                   (range ? range_text(*range) : "all " + std::to_string(frames) + " frames");
        }
    }
    check_output(app, options);
    const raster::AnimationPath path = options.transparent ? raster::AnimationPath::anim : options.encoder;
    raster::AnimationEncoder encoder(options.width, options.height, spacing_ms, {options.effort, path, options.threads_in_use()});
    Progress progress(app.get_name(), options);
    for (int i = begin; i < end; ++i) {
        if (i != begin || !drawn_first) {  // the first frame may be drawn already, to compare
            alpha.clear();
            render(frame, i, alpha);
        }
        if (i == begin) {
            progress.pause();
            preview(app, options, frame, alpha);
        }
        encoder.add_frame(frame, alpha);
        progress.frame(i - begin + 1, end - begin);
    }
    progress.stage("assembling the animation");
    std::vector<std::uint8_t> bytes = encoder.finish();
    if (range) bytes = raster::mark_frame_range(bytes, *range);
    deliver(options, bytes);
    return describe_destination(options) + ": " + std::to_string(options.width) + "x" +
           std::to_string(options.height) + ", " + std::to_string(end - begin) + " frames, " +
           std::to_string(std::int64_t{end - begin} * spacing_ms) + " ms, " + std::to_string(bytes.size()) + " bytes" +
           (range ? ", " + range_text(*range) : "");
}

std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                             const std::function<void(raster::Framebuffer&, int)>& render) {
    return export_animation(app, options, frames, fps,
                            [&](raster::Framebuffer& frame, int index, std::vector<std::uint8_t>&) { render(frame, index); });
}
