#include "animation_export.hpp"

#include "chosen_frames.hpp"
#include "delivery.hpp"
#include "finished_picture.hpp"
#include "numbered_frames.hpp"
#include "progress.hpp"

#include <raster/io/frame_timing.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/io/webp_parts.hpp>

#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace {

// Whether the output already holds what this run would write: this range (or none, for a
// whole clip), this size and frame timing, and this run's first frame, drawn to compare.
bool already_complete(const ExportOptions& options, const std::optional<raster::FrameRange>& range, int count,
                      int spacing_ms, const raster::Framebuffer& first) {
    const std::filesystem::path path = options.output;
    try {
        const std::vector<std::uint8_t> bytes = raster::read_input_file(
            path,
            raster::InputRules{"animation", raster::kMaxWebpFileBytes, raster::looks_like_webp, 12, "a WebP file", {}});
        if (raster::frame_range_of(bytes) != range) return false;
        bool same_first = false;
        std::int64_t lasts_ms = 0;
        int frames = 0;
        const raster::WebpInfo info = raster::for_each_webp_frame(path, [&](const raster::DecodedFrame& frame) {
            if (frames++ == 0) same_first = frame.image == first;
            // libwebp's own encoder lengthens a frame instead of repeating it, down to a still (no duration).
            const std::int64_t lasts =
                frame.duration_ms > 0 ? frame.duration_ms : raster::frames_length_ms(count, spacing_ms);
            lasts_ms += lasts;
            return same_first && lasts % spacing_ms == 0;
        });
        return same_first && info.width == options.width && info.height == options.height &&
               lasts_ms == raster::frames_length_ms(count, spacing_ms);
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                             const RenderFrame& render) {
    if (!options.frames_dir.empty()) return export_numbered_frames(app, options, frames, fps, render);
    if (options.image_format() == ImageFormat::png) {
        throw std::runtime_error(
            "a PNG file holds one picture: write the animation to a .webp file, or to numbered PNG "
            "frames with --frames-dir DIR");
    }
    const std::optional<raster::FrameRange> range = chosen_range(options, frames, fps);
    const int begin = range ? range->first : 0, end = range ? range->last + 1 : frames;
    const int spacing_ms = raster::frame_spacing_ms(fps);
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
    raster::AnimationEncoder encoder(options.width, options.height, spacing_ms,
                                     {options.effort, path, options.threads_in_use()});
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
    return describe_destination(options) + ": " + std::to_string(options.width) + "x" + std::to_string(options.height) +
           ", " + std::to_string(end - begin) + " frames, " +
           std::to_string(raster::frames_length_ms(end - begin, spacing_ms)) + " ms, " + std::to_string(bytes.size()) +
           " bytes" + (range ? ", " + range_text(*range) : "");
}

std::string export_animation(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                             const std::function<void(raster::Framebuffer&, int)>& render) {
    return export_animation(
        app, options, frames, fps,
        [&](raster::Framebuffer& frame, int index, std::vector<std::uint8_t>&) { render(frame, index); });
}
