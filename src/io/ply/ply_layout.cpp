#include "io/ply/ply_layout.hpp"

#include "io/ply_header.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace raster::detail {
namespace {

constexpr std::array<std::pair<std::string_view, PlyType>, 16> kTypeNames{{
    {"char", PlyType::int8},
    {"int8", PlyType::int8},
    {"uchar", PlyType::uint8},
    {"uint8", PlyType::uint8},
    {"short", PlyType::int16},
    {"int16", PlyType::int16},
    {"ushort", PlyType::uint16},
    {"uint16", PlyType::uint16},
    {"int", PlyType::int32},
    {"int32", PlyType::int32},
    {"uint", PlyType::uint32},
    {"uint32", PlyType::uint32},
    {"float", PlyType::float32},
    {"float32", PlyType::float32},
    {"double", PlyType::float64},
    {"float64", PlyType::float64},
}};

PlyType type_named(std::string_view word) {
    for (const auto& [name, type] : kTypeNames) {
        if (name == word) return type;
    }
    throw std::runtime_error("the PLY header names an unknown type '" + printable(word, 40) + "'");
}

// Lines and elements that only assimp's reader gives meaning to.
bool only_assimp_reads(const PlyElement& element) {
    if (element.name == "material" || element.name == "tristrips" || element.name == "TextureFile") return true;
    if (element.name != "face") return false;
    return std::any_of(element.properties.begin(), element.properties.end(),
                       [](const PlyProperty& p) { return p.name == "texcoord" || p.name == "material_index"; });
}

}  // namespace

int ply_type_bytes(PlyType type) noexcept {
    switch (type) {
    case PlyType::int8:
    case PlyType::uint8: return 1;
    case PlyType::int16:
    case PlyType::uint16: return 2;
    case PlyType::float64: return 8;
    default: return 4;
    }
}

bool ply_type_signed(PlyType type) noexcept {
    return type == PlyType::int8 || type == PlyType::int16 || type == PlyType::int32;
}

bool ply_type_integer(PlyType type) noexcept { return type != PlyType::float32 && type != PlyType::float64; }

int ply_corner_list(const PlyElement& element) noexcept {
    int found = -1;
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) found = static_cast<int>(k);
    }
    return found;
}

PlyLayout ply_layout(std::span<const std::uint8_t> head) {
    const std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());
    PlyLayout layout;
    std::size_t start = 0;
    for (;;) {
        const std::size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos) throw std::runtime_error("the PLY header has no end_header line");
        std::string_view line = text.substr(start, newline - start);
        if (line.ends_with('\r')) line.remove_suffix(1);
        start = newline + 1;
        ++layout.header_lines;
        const std::vector<std::string_view> words = ply_words(line);
        if (words.empty()) continue;
        if (words[0] == "end_header" && words.size() == 1) break;  // as ply_header_problem ends the header
        if (words[0] == "format" && words.size() > 1) {
            layout.encoding = words[1] == "ascii"               ? PlyEncoding::ascii
                              : words[1] == "binary_big_endian" ? PlyEncoding::big_endian
                                                                : PlyEncoding::little_endian;
        }
        if (words[0] == "comment" && words.size() > 1 && words[1] == "TextureFile") layout.needs_assimp = true;
        if (words[0] == "element" && words.size() == 3) {
            PlyElement element{printable(words[1]), 0, {}};  // names go into messages
            std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
            for (const PlyElement& other : layout.elements) {
                if (other.name == element.name)
                    throw std::runtime_error("the PLY header declares the element '" + printable(words[1], 40) +
                                             "' twice");
            }
            layout.elements.push_back(std::move(element));
        }
        if (words[0] == "property" && !layout.elements.empty()) {
            PlyProperty property;
            if (words.size() == 5 && words[1] == "list") {
                property = {printable(words[4]), type_named(words[3]), true, type_named(words[2])};
            } else if (words.size() == 3) {
                property = {printable(words[2]), type_named(words[1]), false, PlyType::uint8};
            }
            layout.elements.back().properties.push_back(std::move(property));
        }
    }
    layout.header_bytes = start;
    for (const PlyElement& element : layout.elements)
        layout.needs_assimp = layout.needs_assimp || only_assimp_reads(element);
    return layout;
}

std::uint64_t ply_least_bytes(const PlyElement& element, bool ascii) noexcept {
    std::uint64_t bytes = 0;
    for (const PlyProperty& p : element.properties)
        bytes += ascii ? 2U : static_cast<std::uint64_t>(ply_type_bytes(p.list ? p.count_type : p.type));
    return std::max<std::uint64_t>(bytes, 1);
}

}  // namespace raster::detail
