#include "exporter.hpp"

#include <raster/io/png.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace {

// DIR/0000.png, DIR/0001.png, ...: printf's %04d, the name ffmpeg's -i DIR/%04d.png reads.
std::filesystem::path numbered(const std::filesystem::path& dir, int index) {
    char name[32];
    std::snprintf(name, sizeof name, "%04d.png", index);
    return dir / name;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Writes every frame of an animated WebP as a numbered PNG file, composited as a player shows it, "
                 "for video tools; the line it prints says how long the frames last.",
                 "webp-frames");
    app.footer("Examples:\n"
               "  webp-frames spin.webp frames     # frames/0000.png, frames/0001.png, ...\n"
               "  ffmpeg -framerate 50 -i frames/%04d.png spin.mp4\n"
               "  tools/make-webm.sh spin.webp     # does both, for WebM video");
    configure_app(app);
    std::string input;
    app.add_option("input", input, "The animated (or still) WebP file to read")->required()->option_text("FILE");
    std::string dir;
    app.add_option("dir", dir, "Directory for the frames, made if missing; DIR/0000.png is frame 0")->required()->option_text("DIR");
    ExportOptions options{""};
    app.add_flag("-q,--quiet", options.quiet, "Print nothing when all goes well");

    return run_exporter(app, options, argc, argv, [&] {
        if (raster::FileIdentity identity; raster::identity_of(input, identity)) options.inputs.push_back({input, identity, "animation"});
        std::error_code error;
        std::filesystem::create_directories(dir, error);
        if (error || !std::filesystem::is_directory(dir)) {
            throw std::runtime_error("cannot make the frames directory '" + raster::printable(dir) + "'" +
                                     (error ? ": " + error.message() : ": a file of that name is in the way"));
        }
        // Frames of another animation left here would follow ours into a video tool's %04d.png.
        if (std::filesystem::exists(numbered(dir, 0), error)) {
            throw std::runtime_error("'" + raster::printable(dir) + "' already holds frames (" + numbered(dir, 0).filename().string() +
                                     "); choose an empty directory");
        }
        int count = 0, shortest = 0, longest = 0;
        std::uintmax_t bytes = 0;
        const raster::WebpInfo info = raster::for_each_webp_frame(input, [&](const raster::DecodedFrame& frame) {
            // An opaque frame stays RGB; a transparent one keeps its alpha.
            const bool opaque = std::all_of(frame.alpha.begin(), frame.alpha.end(), [](std::uint8_t a) { return a == 255; });
            const std::vector<std::uint8_t> png = raster::encode_png(frame.image, opaque ? std::span<const std::uint8_t>() : frame.alpha);
            raster::write_output_file(numbered(dir, count), png, options.policy, options.inputs);
            bytes += png.size();
            shortest = count == 0 ? frame.duration_ms : std::min(shortest, frame.duration_ms);
            longest = std::max(longest, frame.duration_ms);
            ++count;
            return true;
        }, &options.inputs);
        const std::string timing = shortest == longest ? std::to_string(shortest) + " ms each"
                                                       : "lasting " + std::to_string(shortest) + " to " + std::to_string(longest) + " ms";
        return "Wrote " + raster::printable(numbered(dir, 0).string()) + " to " + numbered(dir, count - 1).filename().string() + ": " +
               std::to_string(count) + " frames of " + std::to_string(info.width) + "x" + std::to_string(info.height) + ", " + timing +
               ", " + std::to_string(bytes) + " bytes";
    });
}
