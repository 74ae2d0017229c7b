#pragma once

#include <cstddef>
#include <functional>

// Work split by index over a few threads started for it: a reader's ranges, a builder's blocks.
namespace raster::detail {

// Calls `work(i)` for each i below `count`, on up to `threads` threads at once (this one among
// them); every call runs, then the exception of the lowest i that threw is rethrown.
void for_each_index(std::size_t count, std::size_t threads, const std::function<void(std::size_t)>& work);

// A thread count as options give it: 0 for available_cores().
[[nodiscard]] std::size_t threads_or_cores(std::size_t threads);

}  // namespace raster::detail
