#include "numbered_frames.hpp"

#include "chosen_frames.hpp"
#include "delivery.hpp"
#include "finished_picture.hpp"
#include "progress.hpp"

#include <raster/io/frame_files.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/output_file.hpp>
#include <raster/io/png.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <vector>

std::string export_numbered_frames(const CLI::App& app, const ExportOptions& options, int frames, int fps,
                                   const RenderFrame& render) {
    const std::filesystem::path dir = options.frames_dir;
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error || !std::filesystem::is_directory(dir)) {
        throw std::runtime_error("cannot make the frames directory '" + raster::printable(dir.string()) + "'" +
                                 (error ? ": " + error.message() : ": a file of that name is in the way"));
    }
    const auto frame_file = [&](int index) { return dir / raster::frame_file_name(index, frames); };
    const std::optional<raster::FrameRange> range = chosen_range(options, frames, fps);
    const int begin = range ? range->first : 0, end = range ? range->last + 1 : frames;
    // Files are written atomically, so a PNG file that decodes is a whole frame from an earlier run.
    std::vector<bool> kept_frames(static_cast<std::size_t>(end - begin));
    for (int i = begin; i < end; ++i) {
        kept_frames[static_cast<std::size_t>(i - begin)] =
            options.skip_existing && holds_finished_picture(frame_file(i), ImageFormat::png);
    }
    const auto skipped = [&](int i) { return kept_frames[static_cast<std::size_t>(i - begin)]; };
    for (int i = begin; i < end; ++i) {
        if (!skipped(i)) raster::check_output_path(frame_file(i), options.policy, options.inputs);
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
        raster::write_output_file(frame_file(i), bytes, options.policy, options.inputs);
        total += bytes.size();
        ++written;
        progress.frame(i - begin + 1, end - begin);
    }
    const int kept = end - begin - written;
    return "Wrote " + raster::printable(frame_file(begin).string()) + " to " + frame_file(end - 1).filename().string() +
           ": " + std::to_string(written) + " PNG frames of " + std::to_string(options.width) + "x" +
           std::to_string(options.height) + " for " + std::to_string(fps) + " fps, " + std::to_string(total) +
           " bytes" + (kept > 0 ? ", " + std::to_string(kept) + " already there kept" : "") +
           (range ? ", " + range_text(*range) : "");
}
