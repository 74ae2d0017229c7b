#include "io/radix_sort.hpp"

#include <array>
#include <cstddef>
#include <utility>

namespace raster::detail {

void radix_sort(std::vector<std::uint64_t>& keys) {
    constexpr std::size_t kBytes = 8;
    std::array<std::array<std::size_t, 256>, kBytes> counts{};
    for (const std::uint64_t key : keys) {
        for (std::size_t b = 0; b < kBytes; ++b) ++counts[b][(key >> (8 * b)) & 0xFF];
    }
    std::vector<std::uint64_t> other;
    for (std::size_t b = 0; b < kBytes; ++b) {
        std::array<std::size_t, 256>& count = counts[b];
        const std::size_t first = keys.empty() ? 0 : (keys.front() >> (8 * b)) & 0xFF;
        if (count[first] == keys.size()) continue;  // every key has this byte: the order stands
        std::size_t at = 0;
        for (std::size_t& c : count) at += std::exchange(c, at);  // each byte value's first place
        if (other.size() != keys.size()) other.resize(keys.size());
        for (const std::uint64_t key : keys) other[count[(key >> (8 * b)) & 0xFF]++] = key;
        keys.swap(other);
    }
}

}  // namespace raster::detail
