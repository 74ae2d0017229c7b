#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

// A PLY header as raster's own reader uses it: the encoding, and each element's properties in
// file order with their types (doc/conventions.md#ply-reader).
namespace raster::detail {

enum class PlyType : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };
enum class PlyEncoding : std::uint8_t { ascii, little_endian, big_endian };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::float32;  // a list's entries
    bool list = false;
    PlyType count_type = PlyType::uint8;  // a list's length
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyLayout {
    PlyEncoding encoding = PlyEncoding::ascii;
    std::vector<PlyElement> elements;
    std::size_t header_bytes = 0;  // where the body begins
    std::size_t header_lines = 0;  // the body's first line is this plus one
    // What only assimp's reader reads (a texture named in a comment, material elements, triangle
    // strips, per-face texture coordinates or material indices): such a file goes to assimp.
    bool needs_assimp = false;
};

[[nodiscard]] int ply_type_bytes(PlyType type) noexcept;
[[nodiscard]] bool ply_type_signed(PlyType type) noexcept;
[[nodiscard]] bool ply_type_integer(PlyType type) noexcept;
// The list of a face element that holds its corners, as assimp finds it (the last so named); -1 for none.
[[nodiscard]] int ply_corner_list(const PlyElement& element) noexcept;

// The fewest bytes one element can take, as ply_counts_problem counts them: its fixed properties
// and lists' lengths in binary, two characters a property in ASCII; at least one.
[[nodiscard]] std::uint64_t ply_least_bytes(const PlyElement& element, bool ascii) noexcept;

// The layout of a header that ply_header_problem passed; throws std::runtime_error for an element
// declared twice, which assimp refused too.
[[nodiscard]] PlyLayout ply_layout(std::span<const std::uint8_t> head);

}  // namespace raster::detail
