#pragma once

#include <raster/io/input_file.hpp>
#include <raster/io/output_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/scenes.hpp>

#include <cstdint>
#include <optional>
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
    std::string frames_dir;             // an animation written as numbered PNG frames into this directory
    std::string frame_range;            // --frame-range A..B: only those frames of the clip, as a marked part
    bool skip_existing = false;         // --skip-existing: an output already complete is not rendered again
    bool transparent = false;           // frames come with alpha: animations take the anim path, which keeps it
    bool show_progress = true;          // off for the pictures of a batch, which are made several at once
    bool preview = false;               // show the picture (an animation's first frame) on the terminal too

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

// ".png" or ".webp": the extension a picture of `format` is named with.
[[nodiscard]] std::string file_extension(ImageFormat format);
// ".PNG" of "shot.PNG" as ".png": the extension a name's format is told by.
[[nodiscard]] std::string lowered_extension(const std::string& name);
