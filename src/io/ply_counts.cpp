// The counts a PLY header declares, checked against the bytes that follow it.
#include "io/ply_header.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <string_view>

namespace raster::detail {
namespace {

struct PlyProperty {
    bool list = false;
    int count_bytes = 0;  // a list's length field
    bool count_signed = false;
    int item_bytes = 0;
};

struct PlyElement {
    std::string_view name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

int type_bytes(std::string_view type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "double" || type == "float64") return 8;
    return 4;  // int, uint, float and their sized names; ply_header_problem refused the rest
}

bool signed_type(std::string_view type) { return !type.starts_with("u"); }

std::string declares(const PlyElement& element) {
    return "the PLY header declares " + std::to_string(element.count) + " '" + std::string(element.name) + "' elements";
}

// A binary list's length, read in the file's byte order; negative lengths come back as huge.
std::uint64_t list_length(const std::uint8_t* at, const PlyProperty& property, bool big_endian) {
    const int n = property.count_bytes;
    std::uint64_t raw = 0;
    for (int k = 0; k < n; ++k) raw = raw << 8U | at[big_endian ? k : n - 1 - k];
    const bool negative = property.count_signed && ((raw >> (8 * n - 1)) & 1U) != 0;
    return negative ? UINT64_MAX : raw;
}

// The fewest bytes one element can take: its fixed properties and its lists' lengths in binary,
// a digit and a space for each property in ASCII; at least one, so that no count is free.
std::uint64_t least_bytes(const PlyElement& element, bool ascii) {
    std::uint64_t bytes = 0;
    for (const PlyProperty& property : element.properties)
        bytes += ascii ? 2U : static_cast<std::uint64_t>(property.list ? property.count_bytes : property.item_bytes);
    return std::max<std::uint64_t>(bytes, 1);
}

std::string too_many(const PlyElement& element, std::size_t left, bool ascii) {
    if (element.count <= left / least_bytes(element, ascii)) return "";
    return declares(element) + ", more than the " + std::to_string(left) +
           " bytes left can hold: the file is cut short, or its header is wrong";
}

std::string cut_short(const PlyElement& element, std::uint64_t item) {
    return "the PLY data is cut short: its header declares " + std::to_string(element.count) + " '" +
           std::string(element.name) + "' elements and the data ends in element " + std::to_string(item + 1);
}

std::string binary_problem(const std::vector<PlyElement>& elements, std::span<const std::uint8_t> body, bool big_endian,
                           std::string& shortfall) {
    std::size_t at = 0;
    for (const PlyElement& element : elements) {
        if (std::string problem = too_many(element, body.size() - at, false); !problem.empty()) return problem;
        if (std::none_of(element.properties.begin(), element.properties.end(),
                         [](const PlyProperty& p) { return p.list; })) {
            // Elements of one size (a point cloud's vertices): checked at once, not one by one.
            const std::uint64_t size = least_bytes(element, false);
            if (element.count * size > body.size() - at) {
                shortfall = cut_short(element, (body.size() - at) / size);
                return "";
            }
            at += static_cast<std::size_t>(element.count * size);
            continue;
        }
        for (std::uint64_t i = 0; i < element.count; ++i) {
            for (const PlyProperty& property : element.properties) {
                std::uint64_t need =
                    static_cast<std::uint64_t>(property.list ? property.count_bytes : property.item_bytes);
                if (need > body.size() - at) {  // the reader keeps what is there
                    shortfall = cut_short(element, i);
                    return "";
                }
                if (property.list) {
                    const std::uint64_t length = list_length(body.data() + at, property, big_endian);
                    at += need;
                    if (length > (body.size() - at) / static_cast<std::uint64_t>(property.item_bytes)) {
                        return "'" + std::string(element.name) + "' item " + std::to_string(i + 1) + " has a list of " +
                               (length == UINT64_MAX ? std::string("negative length")
                                                     : std::to_string(length) + " entries") +
                               ", more than the bytes left can hold";
                    }
                    need = length * static_cast<std::uint64_t>(property.item_bytes);
                }
                at += static_cast<std::size_t>(need);
            }
        }
    }
    return "";
}

std::string ascii_problem(const std::vector<PlyElement>& elements, std::string_view body, std::string& shortfall) {
    std::size_t at = 0;
    for (const PlyElement& element : elements) {
        if (std::string problem = too_many(element, body.size() - at, true); !problem.empty()) return problem;
        for (std::uint64_t i = 0; i < element.count; ++i) {
            if (at >= body.size()) {  // the reader keeps what is there
                shortfall = cut_short(element, i);
                return "";
            }
            const std::size_t end = std::min(body.find('\n', at), body.size());
            const std::vector<std::string_view> words = ply_words(body.substr(at, end - at));
            at = end + 1;
            std::size_t word = 0;
            for (const PlyProperty& property : element.properties) {
                if (!property.list) {
                    ++word;
                    continue;
                }
                if (word >= words.size()) break;  // no length written: an empty list, as assimp reads it
                std::uint64_t length = 0;
                const std::string_view text = words[word];
                const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), length);
                if (error != std::errc() || stop != text.data() + text.size() || length > words.size() - word - 1) {
                    return "'" + std::string(element.name) + "' item " + std::to_string(i + 1) +
                           " has a list longer than its line";
                }
                word += 1 + static_cast<std::size_t>(length);
            }
        }
    }
    return "";
}

}  // namespace

std::string ply_counts_problem(std::span<const std::uint8_t> bytes, PlyShape* shape) {
    PlyShape ignored;
    PlyShape& out = shape != nullptr ? *shape : ignored;
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    std::vector<PlyElement> elements;
    std::string_view format;
    std::size_t start = 0;
    for (;;) {
        const std::size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos || start > kMaxPlyHeaderBytes)
            return "the PLY header has no end_header line";
        std::string_view line = text.substr(start, newline - start);
        if (line.ends_with('\r')) line.remove_suffix(1);
        start = newline + 1;
        const std::vector<std::string_view> words = ply_words(line);
        if (words.empty()) continue;
        if (words[0] == "end_header") break;
        if (words[0] == "format" && words.size() > 1) format = words[1];
        if (words[0] == "element" && words.size() == 3) {
            PlyElement element{words[1], 0, {}};
            std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
            elements.push_back(element);
        }
        if (words[0] == "property" && !elements.empty()) {
            if (words.size() == 5 && words[1] == "list") {
                elements.back().properties.push_back(
                    {true, type_bytes(words[2]), signed_type(words[2]), type_bytes(words[3])});
            } else if (words.size() == 3) {
                elements.back().properties.push_back({false, 0, false, type_bytes(words[1])});
            }
        }
    }
    out.vertices = 0;
    for (const PlyElement& element : elements) {
        if (element.name == "vertex") out.vertices += element.count;
    }
    const auto body = bytes.subspan(start);
    if (format == "ascii")
        return ascii_problem(elements, {reinterpret_cast<const char*>(body.data()), body.size()}, out.cut_short);
    return binary_problem(elements, body, format == "binary_big_endian", out.cut_short);
}

}  // namespace raster::detail
