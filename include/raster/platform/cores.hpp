#pragma once

// The machine's cores as this process may use them.
namespace raster {

// The cores this process may run on (its affinity mask), at least 1; a thread count of 0
// anywhere in raster means this many.
[[nodiscard]] int available_cores() noexcept;

}  // namespace raster
