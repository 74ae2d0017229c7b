#include "command_line.hpp"
#include "export_options.hpp"
#include "help_format.hpp"

#include <raster/io/frame_files.hpp>
#include <raster/io/png.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <fcntl.h>
#include <unistd.h>

namespace {

// DIR/0000.png, DIR/0001.png, ...: the names ffmpeg's -i DIR/%04d.png reads.
std::filesystem::path numbered(const std::filesystem::path& dir, int index) {
    return dir / raster::frame_file_name(index);
}

// A hidden directory inside DIR that holds the frames until all are written, removed with
// whatever is left in it when the run ends, so that a failure leaves neither a partial set nor it.
class StagingDir {
public:
    explicit StagingDir(const std::filesystem::path& dir) {
        std::string name = (dir / ".webp-frames-XXXXXX").string();
        if (::mkdtemp(name.data()) == nullptr) {
            throw std::runtime_error("cannot make a temporary directory in '" + raster::printable(dir.string()) +
                                     "': " + std::strerror(errno));
        }
        path_ = name;
    }
    ~StagingDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    StagingDir(const StagingDir&) = delete;
    StagingDir& operator=(const StagingDir&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

// Moves a file to a name that must still be free: an existing file there is never replaced.
bool move_to_free_name(const std::filesystem::path& from, const std::filesystem::path& to) {
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
    if (errno != EINVAL && errno != ENOSYS) return false;
    // A file system without RENAME_NOREPLACE: a hard link also refuses an existing name.
    if (::link(from.c_str(), to.c_str()) != 0) return false;
    ::unlink(from.c_str());
    return true;
}

// Frames of another animation left here would mix with ours in a video tool's %04d.png.
void refuse_old_frames(const std::string& dir, int frame_count) {
    std::error_code error;
    for (int index = 0; index < frame_count; ++index) {
        if (std::filesystem::symlink_status(numbered(dir, index), error).type() !=
            std::filesystem::file_type::not_found) {
            throw std::runtime_error("'" + raster::printable(dir) + "' already holds frames (" +
                                     numbered(dir, index).filename().string() + "); choose an empty directory");
        }
    }
}

// Moves the `count` frames written to `staging` into DIR, each to a name still free; on a
// failure the frames already moved are removed again.
void move_into_place(const std::filesystem::path& staging, const std::string& dir, int count) {
    std::error_code error;
    for (int index = 0; index < count; ++index) {
        if (!move_to_free_name(numbered(staging, index), numbered(dir, index))) {
            const std::string why = std::strerror(errno);
            for (int moved = 0; moved < index; ++moved) std::filesystem::remove(numbered(dir, moved), error);
            throw std::runtime_error("cannot move " + numbered(dir, index).filename().string() + " into '" +
                                     raster::printable(dir) + "': " + why);
        }
    }
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
    app.add_option("dir", dir,
                   "Directory for the frames, made if missing; DIR/0000.png is frame 0. Refused if any frame's "
                   "file is there already; the frames appear together once all are written, or none do")
        ->required()
        ->option_text("DIR");
    ExportOptions options{""};
    app.add_flag("-q,--quiet", options.quiet, "Print nothing when all goes well");

    return run_exporter(app, options, argc, argv, [&] {
        if (raster::FileIdentity identity; raster::identity_of(input, identity))
            options.inputs.push_back({input, identity, "animation"});
        std::error_code error;
        std::filesystem::create_directories(dir, error);
        if (error || !std::filesystem::is_directory(dir)) {
            throw std::runtime_error("cannot make the frames directory '" + raster::printable(dir) + "'" +
                                     (error ? ": " + error.message() : ": a file of that name is in the way"));
        }
        raster::WebpFrameReader reader(input, &options.inputs);
        const raster::WebpInfo& info = reader.info();
        refuse_old_frames(dir, info.frame_count);
        const StagingDir staging(dir);
        int count = 0, shortest = 0, longest = 0;
        std::uintmax_t bytes = 0;
        while (const raster::DecodedFrame* frame = reader.next()) {
            // An opaque frame stays RGB; a transparent one keeps its alpha.
            const bool opaque =
                std::all_of(frame->alpha.begin(), frame->alpha.end(), [](std::uint8_t a) { return a == 255; });
            const std::vector<std::uint8_t> png =
                raster::encode_png(frame->image, opaque ? std::span<const std::uint8_t>() : frame->alpha);
            raster::write_output_file(numbered(staging.path(), count), png, options.policy, options.inputs);
            bytes += png.size();
            shortest = count == 0 ? frame->duration_ms : std::min(shortest, frame->duration_ms);
            longest = std::max(longest, frame->duration_ms);
            ++count;
        }
        move_into_place(staging.path(), dir, count);
        const std::string timing =
            shortest == longest ? std::to_string(shortest) + " ms each"
                                : "lasting " + std::to_string(shortest) + " to " + std::to_string(longest) + " ms";
        return "Wrote " + raster::printable(numbered(dir, 0).string()) + " to " +
               numbered(dir, count - 1).filename().string() + ": " + std::to_string(count) + " frames of " +
               std::to_string(info.width) + "x" + std::to_string(info.height) + ", " + timing + ", " +
               std::to_string(bytes) + " bytes";
    });
}
