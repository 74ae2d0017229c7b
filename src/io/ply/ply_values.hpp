#pragma once

#include "io/ply/ply_layout.hpp"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <system_error>

// One PLY value, from its bytes in either order or from its ASCII text, as a double (which holds
// every value of every PLY type exactly).
namespace raster::detail {

template <typename T>
T ply_load(const std::uint8_t* at, bool swap) noexcept {
    static_assert(sizeof(T) <= 8);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, at, sizeof(T));
    if (swap) {
        for (std::size_t k = 0; k < sizeof(T) / 2; ++k) {
            const unsigned char kept = raw[k];
            raw[k] = raw[sizeof(T) - 1 - k];
            raw[sizeof(T) - 1 - k] = kept;
        }
    }
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
}

// The value of `type` at `at`, written big-endian when `big`.
[[nodiscard]] inline double ply_binary_value(const std::uint8_t* at, PlyType type, bool big) noexcept {
    const bool swap = big == (std::endian::native == std::endian::little);
    switch (type) {
    case PlyType::int8: return static_cast<std::int8_t>(at[0]);
    case PlyType::uint8: return at[0];
    case PlyType::int16: return ply_load<std::int16_t>(at, swap);
    case PlyType::uint16: return ply_load<std::uint16_t>(at, swap);
    case PlyType::int32: return ply_load<std::int32_t>(at, swap);
    case PlyType::uint32: return ply_load<std::uint32_t>(at, swap);
    case PlyType::float32: return static_cast<double>(ply_load<float>(at, swap));
    case PlyType::float64: return ply_load<double>(at, swap);
    }
    return 0.0;
}

// The value `word` writes for `type` (a leading '+' allowed, floats in any form from_chars
// reads, "nan" and "inf" included); false when it writes none.
[[nodiscard]] inline bool ply_text_value(std::string_view word, PlyType type, double& value) noexcept {
    if (word.starts_with('+')) word.remove_prefix(1);
    const char* first = word.data();
    const char* last = word.data() + word.size();
    std::from_chars_result result{};
    if (type == PlyType::float32) {
        float f = 0.0F;
        result = std::from_chars(first, last, f);
        if (result.ec == std::errc::result_out_of_range) {  // as the float the written number rounds to
            double d = 0.0;
            result = std::from_chars(first, last, d);
            f = static_cast<float>(d);
        }
        value = static_cast<double>(f);
    } else if (type == PlyType::float64) {
        result = std::from_chars(first, last, value);
    } else if (ply_type_signed(type)) {
        std::int64_t i = 0;
        result = std::from_chars(first, last, i);
        value = static_cast<double>(i);
    } else {
        std::uint64_t u = 0;
        result = std::from_chars(first, last, u);
        value = static_cast<double>(u);
    }
    return !word.empty() && result.ec == std::errc() && result.ptr == last;
}

// The next word of `line` (split at spaces and tabs), taken off its front; empty at its end.
[[nodiscard]] inline std::string_view ply_next_word(std::string_view& line) noexcept {
    std::size_t at = 0;
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
    std::size_t end = at;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
    const std::string_view word = line.substr(at, end - at);
    line.remove_prefix(end);
    return word;
}

}  // namespace raster::detail
