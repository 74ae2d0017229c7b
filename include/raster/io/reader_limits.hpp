#pragma once

#include <cstdint>

// What reading one model may cost: a reader raster does not own runs in a process of its own that
// a crash, a memory bomb or an endless loop takes down alone; raster's own readers are held to
// the memory by their counts (doc/conventions.md#reader-process).
namespace raster {

class ReaderService;

struct ReaderLimits {
    // Address space the reader may add to what the process holds; 0 takes default_max_memory().
    std::uint64_t max_memory = 0;
    // Seconds of processor and of wall-clock time.
    double max_seconds = 120.0;
    // false reads in this process, unbounded: for the lab's measure of what the process costs.
    bool separate_process = true;
    // Where set, the reader is forked from this small process rather than from the caller.
    const ReaderService* service = nullptr;
};

// Half of the physical memory, or 1 GiB where it cannot be found.
[[nodiscard]] std::uint64_t default_max_memory() noexcept;

}  // namespace raster
