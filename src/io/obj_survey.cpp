#include "io/obj_survey.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace raster::detail {

namespace {

// v, vt and vn: what a face corner names, in the order of the corner's fields.
enum Kind : std::size_t { kPosition, kUv, kNormal };
constexpr std::array<const char*, 3> kKindName = {"vertex", "texture coordinate", "normal"};
constexpr std::array<const char*, 3> kKindPlural = {"vertices", "texture coordinates", "normals"};
// How many leading numbers of each kind raster uses (vt's third, like v's colours, is ignored),
// and how many must be there (a texture coordinate may give u alone).
constexpr std::array<std::size_t, 3> kUsedNumbers = {3, 2, 3};
constexpr std::array<std::size_t, 3> kNeededNumbers = {3, 1, 3};

// A coordinate that is not the number it should be: where, and why.
struct BadNumber {
    std::size_t index;
    std::size_t line;
    std::string problem;
};

// Words as tinyobjloader splits them: at spaces and tabs only.
std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    constexpr std::string_view kSpace = " \t";
    for (std::size_t start = line.find_first_not_of(kSpace); start != std::string_view::npos;) {
        const std::size_t end = std::min(line.find_first_of(kSpace, start), line.size());
        words.push_back(line.substr(start, end - start));
        start = line.find_first_not_of(kSpace, end);
    }
    return words;
}

// Why a word is not a finite coordinate that a float holds, or "" when it is one (a number too
// small for a float is read as 0, as written).
std::string number_problem(std::string_view word) {
    const std::string quoted = "'" + printable(word, 40) + "'";
    std::string_view digits = word;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);  // from_chars takes no '+'
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || (error != std::errc() && error != std::errc::result_out_of_range)) {
        return quoted + ", which is not a number";
    }
    if (error == std::errc::result_out_of_range) {
        const std::string copy(digits);
        errno = 0;
        value = std::strtod(copy.c_str(), nullptr);  // tells overflow (huge) from underflow (tiny)
        if (std::abs(value) <= 1.0) return "";
    }
    if (!std::isfinite(value)) return quoted + ", which is not a finite number";
    if (std::abs(value) > std::numeric_limits<float>::max())
        return quoted + ", which is beyond the largest coordinate raster stores";
    return "";
}

// One index of a face corner, OBJ's way: 1 is the first defined so far, -1 the last one.
// Returns the index from 0, or throws with the reason.
std::size_t resolved_index(std::string_view text, std::size_t defined, Kind kind, const std::string& at,
                           std::string_view statement) {
    const std::string what = kKindName[kind];
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        throw std::runtime_error(at + "'" + printable(text, 40) + "' is not a " + what + " index");
    }
    if (value == 0) throw std::runtime_error(at + what + " index 0: OBJ counts from 1");
    const long long resolved = value > 0 ? value : static_cast<long long>(defined) + value + 1;
    if (resolved < 1 || resolved > static_cast<long long>(defined)) {
        throw std::runtime_error(at + std::string(statement) + " names " + what + " " + std::to_string(value) +
                                 ", but " + std::to_string(defined) + (defined == 1 ? " is" : " are") +
                                 " defined before it");
    }
    return static_cast<std::size_t>(resolved - 1);
}

// The statement a line makes, as tinyobjloader recognises it: its keyword followed by a space
// or a tab ("v" alone at the end of a line is no vertex to it, and so none to us).
std::string_view keyword_of(std::string_view line) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string_view::npos) return {};
    const std::size_t end = line.find_first_of(" \t", start);
    return end == std::string_view::npos ? std::string_view() : line.substr(start, end - start);
}

}  // namespace

ObjSurvey survey_obj(const std::string& name, std::size_t max_corners,
                     const std::function<void(const std::function<void(std::string_view, std::size_t)>&)>& lines) {
    ObjSurvey survey;
    std::array<std::vector<BadNumber>, 3> bad;
    std::size_t empty_mtllib_line = 0, empty_mtllib_count = 0;
    const auto check_used = [&](Kind kind, std::size_t index, const std::string& at, std::string_view statement) {
        auto& list = bad[kind];
        const auto found = std::lower_bound(list.begin(), list.end(), index,
                                            [](const BadNumber& b, std::size_t i) { return b.index < i; });
        if (found == list.end() || found->index != index) return;
        throw std::runtime_error(at + "the " + std::string(statement) + " uses " + kKindName[kind] + " " +
                                 std::to_string(index + 1) + ", but line " + std::to_string(found->line) +
                                 " gives it " + found->problem);
    };
    lines([&](std::string_view line, std::size_t number) {
        if (number == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);  // a UTF-8 byte order mark
        const std::string_view keyword = keyword_of(line);
        const auto kind = keyword == "v"    ? kPosition
                          : keyword == "vt" ? kUv
                          : keyword == "vn" ? kNormal
                                            : std::size_t{3};
        const bool drawn = keyword == "f" || keyword == "p" || keyword == "l";
        if (keyword.empty() || (kind == 3 && !drawn && keyword != "mtllib" && keyword != "usemtl")) return;
        const std::vector<std::string_view> words = words_of(line);
        const std::string at = name + ":" + std::to_string(number) + ": ";
        if (kind < 3) {
            std::string problem;
            for (std::size_t w = 1; w < words.size() && w <= kUsedNumbers[kind] && problem.empty(); ++w)
                problem = number_problem(words[w]);
            if (problem.empty() && words.size() - 1 < kNeededNumbers[kind]) {
                problem = "only " + std::to_string(words.size() - 1) + " of its " +
                          std::to_string(kNeededNumbers[kind]) + " coordinates";
            }
            if (!problem.empty()) bad[kind].push_back({survey.defined[kind], number, std::move(problem)});
            if (kind == kPosition && words.size() - 1 >= 6) ++survey.coloured_vertices;
            ++survey.defined[kind];
        } else if (drawn) {
            const bool face = keyword == "f";
            const std::string_view statement = face ? "face" : keyword == "p" ? "point" : "line";
            if (face && words.size() - 1 > max_corners) {
                throw std::runtime_error(at + "a face of more than " + std::to_string(max_corners) + " corners");
            }
            if (face && words.size() < 4) ++survey.skipped_faces;
            if (face && words.size() - 1 >= 256) survey.large_faces.emplace_back(survey.faces, words.size() - 1);
            if (face && words.size() >= 4) ++survey.faces;
            if (keyword == "p") survey.points += words.size() - 1;
            if (keyword == "l" && words.size() >= 3) survey.segments += words.size() - 2;
            if (keyword == "l" && words.size() < 3 && survey.short_line == 0) survey.short_line = number;
            for (std::size_t w = 1; w < words.size(); ++w) {
                const std::string_view corner = words[w];
                std::array<std::string_view, 3> fields{};
                std::size_t count = 0;
                for (std::size_t start = 0; count < 3; ++count) {
                    const std::size_t slash = corner.find('/', start);
                    fields[count] =
                        corner.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
                    if (slash == std::string_view::npos) break;
                    start = slash + 1;
                }
                const bool well_formed = count < 3 && !fields[0].empty() && (count != 1 || !fields[1].empty()) &&
                                         (count != 2 || !fields[2].empty());
                if (!well_formed) {
                    throw std::runtime_error(at + (face ? "corner '" : "vertex '") + printable(corner, 40) +
                                             "' is not of the form v, v/vt, v/vt/vn or v//vn");
                }
                for (std::size_t k = 0; k <= count; ++k) {
                    if (fields[k].empty()) continue;  // v//vn
                    const auto field_kind = static_cast<Kind>(k);
                    check_used(field_kind, resolved_index(fields[k], survey.defined[k], field_kind, at, statement), at,
                               statement);
                }
            }
        } else if (keyword == "mtllib") {
            if (words.size() < 2 && empty_mtllib_count++ == 0) empty_mtllib_line = number;
            for (std::size_t w = 1; w < words.size(); ++w) survey.library_lines.emplace(std::string(words[w]), number);
        } else if (words.size() >= 2 && survey.material_lines.emplace(std::string(words[1]), number).second) {
            survey.materials.push_back({std::string(words[1]), number});
        }
    });
    if (empty_mtllib_count > 0) {
        survey.warnings.push_back(name + ":" + std::to_string(empty_mtllib_line) + ": mtllib names no file" +
                                  (empty_mtllib_count > 1
                                       ? " (nor do " + std::to_string(empty_mtllib_count - 1) + " more mtllib lines)"
                                       : ""));
    }
    if (survey.short_line != 0)
        survey.warnings.push_back(name + ":" + std::to_string(survey.short_line) +
                                  ": a line (l) of fewer than 2 vertices draws nothing; skipped");
    // One warning per kind, however many lines repeat its cause.
    for (std::size_t kind = 0; kind < 3; ++kind) {
        if (bad[kind].empty()) continue;  // a face using one would have thrown
        const BadNumber& first = bad[kind].front();
        const std::size_t more = bad[kind].size() - 1;
        survey.warnings.push_back(
            name + ":" + std::to_string(first.line) + ": " + kKindName[kind] + " " + std::to_string(first.index + 1) +
            " has " + first.problem + "; no face uses it" +
            (more > 0 ? " (nor " + std::to_string(more) + " more such " + kKindPlural[kind] + ")" : ""));
    }
    return survey;
}

}  // namespace raster::detail
