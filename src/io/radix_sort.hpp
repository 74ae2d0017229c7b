#pragma once

#include <cstdint>
#include <vector>

// Sorting many 64-bit keys in linear time, for pairing edges and welding positions (issue 31).
namespace raster::detail {

// Sorts `keys` ascending, a byte at a time from the lowest, skipping bytes every key shares.
void radix_sort(std::vector<std::uint64_t>& keys);

}  // namespace raster::detail
