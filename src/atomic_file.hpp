#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace raster {

// A file that appears whole or not at all: bytes go to a temporary file beside the target,
// which replaces the target only on commit. Destroyed uncommitted, it leaves no trace.
class AtomicFile {
public:
    // Claims the temporary file now, so a bad destination fails before any work is done.
    // Throws std::runtime_error with a one-line reason.
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    // Writes the bytes and renames the temporary file over the target.
    void commit(std::span<const std::uint8_t> bytes);

private:
    std::filesystem::path target_;
    std::filesystem::path temporary_;
    int descriptor_ = -1;
};

}  // namespace raster
