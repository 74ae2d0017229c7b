#pragma once

#include <raster/io/output_file.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/scenes.hpp>
#include <raster/io/webp.hpp>
#include <raster/io/webp_parts.hpp>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

// The file formats written: lossless WebP (the default), or PNG for tools that want it.
enum class ImageFormat { webp, png };

// What every exporter takes: where to write, how big, how hard to compress, what to say.
struct ExportOptions {
    explicit ExportOptions(std::string default_output) : output(std::move(default_output)) {}

    std::string output;  // "-" writes to standard output
    int width = raster::kSceneWidth;
    int height = raster::kSceneHeight;
    raster::Effort effort = raster::Effort::balanced;
    bool quiet = false;
    bool progress = false;
    raster::OutputPolicy policy;
    raster::AnimationPath encoder = raster::AnimationPath::parallel;
    int threads = 0;  // for rendering bands and encoding frames; 0: one per core
    int samples = 1;  // per pixel, for anti-aliasing (--samples); 0 until a program's default is known
    std::vector<raster::InputRecord> inputs;  // every file read: no output may replace one
    // When set, deliver() keeps the picture here instead of writing it: a batch writes a picture
    // that would replace an existing file only after every model has been read.
    std::vector<struct HeldPicture>* held = nullptr;
    std::optional<ImageFormat> format;  // default: PNG for a name ending in .png, else WebP
    std::string frames_dir;  // an animation written as numbered PNG frames into this directory
    std::string frame_range;  // --frame-range A..B: only those frames of the clip, as a marked part
    bool skip_existing = false;  // --skip-existing: an output already complete is not rendered again
    bool transparent = false;  // frames come with alpha: animations take the anim path, which keeps it
    bool show_progress = true;  // off for the pictures of a batch, which are made several at once
    bool preview = false;  // show the picture (an animation's first frame) on the terminal too

    [[nodiscard]] ImageFormat image_format() const;

    // More threads than the cores this process may run on would only hold memory: the count
    // asked for is capped there, and 0 takes one per such core.
    [[nodiscard]] int threads_in_use() const;
    [[nodiscard]] raster::RenderOptions render_options() const { return {threads_in_use(), samples}; }
};

// A picture deliver() kept for later, with where it goes.
struct HeldPicture {
    ExportOptions options;
    std::vector<std::uint8_t> bytes;
};

// A CLI11 app whose help is wrapped to 80 columns and whose --version names the program.
void configure_app(CLI::App& app);

// OUTPUT / -o, --format, --effort, --quiet, --progress, --follow-symlinks, --preview.
void add_output_options(CLI::App& app, ExportOptions& options);
// --width and --height, then the output options.
void add_export_options(CLI::App& app, ExportOptions& options);
// A decimal integer in [low, high]; anything else is a usage error that says so.
CLI::Option* add_integer_option(CLI::App& app, const std::string& name, int& value, int low, int high,
                                const std::string& help);
// Reads a decimal number into `value`: "" when it is finite, else why not, in the option's terms.
std::string read_finite(const std::string& given, double& value);
// A decimal number that is finite and within [low, high] (both ends open when `open_ends`); the
// error says in the option's terms what is wrong ("must be finite", "must be positive").
CLI::Validator finite_number(double low, double high, bool open_ends = false, const std::string& unit = "");
// Accepts only one of `names` (any case) and lower-cases it; the error lists the names.
CLI::Validator one_of(const std::vector<std::string>& names);

// A choice taken by name only: numbers and unknown names are usage errors that list the names.
template <typename Value>
CLI::Option* add_choice_option(CLI::App& app, const std::string& name, Value& value,
                               const std::vector<std::pair<std::string, Value>>& choices,
                               const std::string& help, const std::string& default_name) {
    std::vector<std::string> names;
    for (const auto& choice : choices) names.push_back(choice.first);
    const auto store = [&value, choices](const std::string& given) {
        for (const auto& [choice_name, choice_value] : choices) {
            if (choice_name == given) value = choice_value;
        }
    };
    return app.add_option_function<std::string>(name, store, help)
        ->transform(one_of(names))
        ->option_text(CLI::detail::join(names, "|") + " [" + default_name + "]");
}
void add_style_option(CLI::App& app, raster::CubeStyle& style, const std::string& line_colour);
// --samples 1|2|4|8|16, anti-aliasing. Left 0 when not given, for the program to choose its
// default (`default_text` says which in the help).
void add_samples_option(CLI::App& app, ExportOptions& options, const std::string& default_text);

// Progress on stderr while frames are made: on a terminal, or everywhere with --progress.
class Progress {
public:
    Progress(std::string program, const ExportOptions& options);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void frame(int done, int total);
    void stage(const std::string& what);
    // Clears the open progress line, so that what comes next starts on a clean line.
    void pause();

private:
    void show(const std::string& text);
    std::string program_;
    bool enabled_;
    bool terminal_;
    int last_tenth_ = -1;
    bool line_open_ = false;
};

// Fails early (a bad path, an input of this run, stdout on a terminal) and warns once about a
// name not ending in the format's extension.
void check_output(const CLI::App& app, const ExportOptions& options);
// With --preview, shows the picture on the terminal through the Kitty graphics protocol, or says
// in one line on stderr why it cannot (not with --quiet); the file is written either way.
void preview(const CLI::App& app, const ExportOptions& options, const raster::Framebuffer& image,
             std::span<const std::uint8_t> alpha = {});
// Writes the finished bytes to the output file (atomically) or to standard output.
void deliver(const ExportOptions& options, std::span<const std::uint8_t> bytes);

// Parses the command line; an exit code when the program should stop there: 0 after --help or
// --version, 2 after a usage error (reported in one line on stderr).
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

// Parses the command line and runs `export_file`, which returns the line to report: on stdout,
// or on stderr when the image itself goes to stdout, and not at all with --quiet. Usage errors
// exit 2, failures 1, each with one line on stderr.
int run_exporter(CLI::App& app, const ExportOptions& options, int argc, char** argv,
                 const std::function<std::string()>& export_file);

// Draws a frame and, for a transparent background, fills `alpha` with its coverage (one byte
// per pixel); left empty, the frame is opaque.
using RenderStill = std::function<void(raster::Framebuffer&, std::vector<std::uint8_t>& alpha)>;
using RenderFrame = std::function<void(raster::Framebuffer&, int index, std::vector<std::uint8_t>& alpha)>;

// Renders one frame of the chosen size, writes it as a still (WebP or PNG) and returns the line
// to report: "Wrote out.webp: 800x600 still, 4211 bytes".
std::string export_still(const CLI::App& app, const ExportOptions& options, const RenderStill& render);
// A picture encoded and the line that will report it; `written` when it is already on disk.
struct FinishedPicture {
    std::vector<std::uint8_t> bytes;
    std::string report;
    bool written = false;
};
// The same in steps: checks the output and renders now, and returns the step that encodes, which
// may run on another thread while the next picture is drawn; deliver() then writes the bytes.
std::function<FinishedPicture()> render_still(const CLI::App& app, const ExportOptions& options, const RenderStill& render);
std::string export_still(const CLI::App& app, const ExportOptions& options,
                         const std::function<void(raster::Framebuffer&)>& render);
// --fps 1..95, with the browsers' 10 ms rule in its help, --encoder parallel|anim,
// --frames-dir DIR, --frame-range A..B and --skip-existing.
void add_animation_options(CLI::App& app, int& fps, ExportOptions& options);
// A regular file (not a link) that is not empty.
[[nodiscard]] bool is_nonempty_regular_file(const std::filesystem::path& path);
// --skip-existing: whether `path` is a finished picture of `format`, a regular file (not a link)
// that is not empty and decodes whole; anything else under that name is drawn again.
[[nodiscard]] bool holds_finished_picture(const std::filesystem::path& path, ImageFormat format);
// Reads "A..B" or "A:B" (decimal, 0 <= A <= B); false for anything else.
bool parse_frame_range(const std::string& text, int& first, int& last);
// Renders `frames` frames at `fps` into a looping animation, writes it and returns the line to
// report: "Wrote out.webp: 800x600, 360 frames, 7200 ms, 205874 bytes". With --frames-dir the
// frames are numbered PNG files in that directory instead.
// With --frame-range only those frames are rendered, exactly as in the whole run, into an
// animation marked with its range (webp_parts.hpp) or into their own numbered files.
std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps, const RenderFrame& render);
std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                             const std::function<void(raster::Framebuffer&, int)>& render);
