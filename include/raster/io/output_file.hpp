#pragma once

#include <raster/io/input_file.hpp>

#include <cstdint>
#include <filesystem>
#include <span>

// Output files that appear whole or not at all and never replace what is not a regular file.
// Every failure throws std::runtime_error with a one-line reason.
namespace raster {

struct OutputPolicy {
    // Write through a symbolic link to the file it names; otherwise a link is refused.
    bool follow_symlinks = false;
};

// Checks, before any work, that `path` can be written: its directory exists and takes a new
// file, and the path is absent or a regular file (or, by policy, a link to one) that is none
// of the `inputs` this run read: an output never replaces what it was made from.
void check_output_path(const std::filesystem::path& path, OutputPolicy policy = {},
                       std::span<const InputRecord> inputs = {});

// Writes the bytes to a temporary file beside the target and renames it over the target.
// A new file gets 0666 less the umask; a replaced file keeps its mode. SIGINT, SIGTERM and
// SIGHUP wait while the temporary file exists, on whichever thread they land (HeldSignals), so
// an interrupt leaves the old file or the new and then ends the program as it would have.
// The `inputs` are checked again just before the rename.
void write_output_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes, OutputPolicy policy = {},
                       std::span<const InputRecord> inputs = {});

}  // namespace raster
