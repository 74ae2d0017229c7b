#include "io/ply_header.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <sstream>
#include <string_view>
#include <vector>

namespace raster::detail {
namespace {

constexpr std::array<std::string_view, 16> kTypes{"char",  "uchar",  "short",   "ushort", "int",   "uint",
                                                  "float", "double", "int8",    "uint8",  "int16", "uint16",
                                                  "int32", "uint32", "float32", "float64"};

bool is_type(std::string_view word) { return std::find(kTypes.begin(), kTypes.end(), word) != kTypes.end(); }

bool is_count(std::string_view word) {
    std::uint64_t count = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), count);
    return !word.empty() && error == std::errc() && end == word.data() + word.size();
}

// "" when one header line is well formed, else what is wrong with it.
std::string line_problem(const std::vector<std::string_view>& words, int number, bool& format_seen,
                         bool& element_seen) {
    const std::string_view key = words.empty() ? std::string_view() : words[0];
    if (number == 1) return key == "ply" && words.size() == 1 ? "" : "does not begin with 'ply'";
    if (key == "comment" || key == "obj_info") return "";
    if (!format_seen) {
        format_seen = words.size() == 3 && key == "format" && words[2] == "1.0" &&
                      (words[1] == "ascii" || words[1] == "binary_little_endian" || words[1] == "binary_big_endian");
        return format_seen ? "" : "has no 'format ascii|binary_little_endian|binary_big_endian 1.0' line after 'ply'";
    }
    if (key == "element") {
        element_seen = true;
        return words.size() == 3 && is_count(words[2]) ? "" : "has an element line that is not 'element NAME COUNT'";
    }
    if (key == "property") {
        if (!element_seen) return "has a property before any element";
        const bool scalar = words.size() == 3 && is_type(words[1]);
        const bool list = words.size() == 5 && words[1] == "list" && is_type(words[2]) && is_type(words[3]);
        return scalar || list
                   ? ""
                   : "has a property line that is not 'property TYPE NAME' or 'property list TYPE TYPE NAME'";
    }
    return "";  // other lines (Blender 2.4 wrote a bare "Created by ...") are skipped, as assimp skips them
}

}  // namespace

std::vector<std::string_view> ply_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t at = 0;
    while (true) {
        at = line.find_first_not_of(" \t", at);
        if (at == std::string_view::npos) return words;
        const std::size_t end = std::min(line.find_first_of(" \t", at), line.size());
        words.push_back(line.substr(at, end - at));
        at = end;
    }
}

std::string ply_header_problem(std::span<const std::uint8_t> bytes) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()),
                                std::min(bytes.size(), kMaxPlyHeaderBytes));
    bool format_seen = false, element_seen = false;
    int number = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t newline = text.find('\n', start);
        if (newline == std::string_view::npos) break;
        std::string_view line = text.substr(start, newline - start);
        if (line.ends_with('\r')) line.remove_suffix(1);
        start = newline + 1;
        ++number;
        const std::vector<std::string_view> words = ply_words(line);
        if (words.size() == 1 && words[0] == "end_header" && number > 1) {
            return format_seen ? "" : "the PLY header ends before its format line";
        }
        if (std::string problem = line_problem(words, number, format_seen, element_seen); !problem.empty()) {
            std::ostringstream said;
            said << "the PLY header " << problem << " (line " << number << ")";
            return said.str();
        }
    }
    return "the PLY header has no end_header line in its first " + std::to_string(kMaxPlyHeaderBytes / 1024) + " KiB";
}

}  // namespace raster::detail
