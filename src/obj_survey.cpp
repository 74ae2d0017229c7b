#include "obj_survey.hpp"

#include <raster/input_file.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace raster::detail {

namespace {

// v, vt and vn: what a face corner names, in the order of the corner's fields.
enum Kind : std::size_t { kPosition, kUv, kNormal };
constexpr std::array<const char*, 3> kKindName = {"vertex", "texture coordinate", "normal"};
// How many leading numbers of each kind raster uses (vt's third, like v's colours, is ignored).
constexpr std::array<std::size_t, 3> kUsedNumbers = {3, 2, 3};

// A coordinate that is not the number it should be: where, and why.
struct BadNumber {
    std::size_t index;
    std::size_t line;
    std::string problem;
};

std::vector<std::string_view> words_of(std::string_view line) {
    std::vector<std::string_view> words;
    constexpr std::string_view kSpace = " \t\r\v\f";
    for (std::size_t start = line.find_first_not_of(kSpace); start != std::string_view::npos;) {
        const std::size_t end = std::min(line.find_first_of(kSpace, start), line.size());
        words.push_back(line.substr(start, end - start));
        start = line.find_first_not_of(kSpace, end);
    }
    return words;
}

// Why a word is not a finite coordinate that a float holds, or "" when it is one.
std::string number_problem(std::string_view word) {
    std::string_view digits = word;
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);  // from_chars takes no '+'
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const std::string quoted = "'" + printable(word, 40) + "'";
    if (end != digits.data() + digits.size() || (error != std::errc() && error != std::errc::result_out_of_range)) {
        return quoted + ", which is not a number";
    }
    if (error == std::errc::result_out_of_range) return quoted + ", which is out of range";
    if (!std::isfinite(value)) return quoted + ", which is not a finite number";
    if (std::abs(value) > std::numeric_limits<float>::max()) return quoted + ", which is beyond the largest coordinate raster stores";
    return "";
}

// One index of a face corner, OBJ's way: 1 is the first defined so far, -1 the last one.
// Returns the index from 0, or throws with the reason.
std::size_t resolved_index(std::string_view text, std::size_t defined, Kind kind, const std::string& at) {
    const std::string what = kKindName[kind];
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) {
        throw std::runtime_error(at + "'" + printable(text, 40) + "' is not a " + what + " index");
    }
    if (value == 0) throw std::runtime_error(at + what + " index 0: OBJ counts from 1");
    const long long resolved = value > 0 ? value : static_cast<long long>(defined) + value + 1;
    if (resolved < 1 || resolved > static_cast<long long>(defined)) {
        throw std::runtime_error(at + "face names " + what + " " + std::to_string(value) + ", but " + std::to_string(defined) +
                                 (defined == 1 ? " is" : " are") + " defined before it");
    }
    return static_cast<std::size_t>(resolved - 1);
}

void remember(std::vector<NamedAt>& list, std::string_view name, std::size_t line) {
    const bool known = std::any_of(list.begin(), list.end(), [&](const NamedAt& n) { return n.name == name; });
    if (!known) list.push_back({std::string(name), line});
}

}  // namespace

ObjSurvey survey_obj(const std::string& name, std::size_t max_corners,
                     const std::function<void(const std::function<void(std::string_view, std::size_t)>&)>& lines) {
    ObjSurvey survey;
    std::array<std::size_t, 3> defined{};
    std::array<std::vector<BadNumber>, 3> bad;
    const auto check_used = [&](Kind kind, std::size_t index, const std::string& at) {
        auto& list = bad[kind];
        const auto found = std::lower_bound(list.begin(), list.end(), index, [](const BadNumber& b, std::size_t i) { return b.index < i; });
        if (found == list.end() || found->index != index) return;
        throw std::runtime_error(at + "the face uses " + kKindName[kind] + " " + std::to_string(index + 1) + ", but line " +
                                 std::to_string(found->line) + " gives it " + found->problem);
    };
    lines([&](std::string_view line, std::size_t number) {
        const std::vector<std::string_view> words = words_of(line);
        if (words.empty()) return;
        const std::string_view keyword = words[0];
        const std::string at = name + ":" + std::to_string(number) + ": ";
        const auto kind = keyword == "v" ? kPosition : keyword == "vt" ? kUv : keyword == "vn" ? kNormal : std::size_t{3};
        if (kind < 3) {
            for (std::size_t w = 1; w < words.size() && w <= kUsedNumbers[kind]; ++w) {
                if (std::string problem = number_problem(words[w]); !problem.empty()) {
                    bad[kind].push_back({defined[kind], number, std::move(problem)});
                    break;
                }
            }
            ++defined[kind];
        } else if (keyword == "f") {
            if (words.size() - 1 > max_corners) {
                throw std::runtime_error(at + "a face of more than " + std::to_string(max_corners) + " corners");
            }
            if (words.size() < 4) ++survey.skipped_faces;
            for (std::size_t w = 1; w < words.size(); ++w) {
                const std::string_view corner = words[w];
                std::array<std::string_view, 3> fields{};
                std::size_t count = 0;
                for (std::size_t start = 0; count < 3; ++count) {
                    const std::size_t slash = corner.find('/', start);
                    fields[count] = corner.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
                    if (slash == std::string_view::npos) break;
                    start = slash + 1;
                }
                const bool well_formed = count < 3 && !fields[0].empty() && (count != 1 || !fields[1].empty()) &&
                                         (count != 2 || !fields[2].empty());
                if (!well_formed) {
                    throw std::runtime_error(at + "corner '" + printable(corner, 40) + "' is not of the form v, v/vt, v/vt/vn or v//vn");
                }
                for (std::size_t k = 0; k <= count; ++k) {
                    if (fields[k].empty()) continue;  // v//vn
                    const auto field_kind = static_cast<Kind>(k);
                    check_used(field_kind, resolved_index(fields[k], defined[k], field_kind, at), at);
                }
            }
        } else if (keyword == "mtllib") {
            if (words.size() < 2) survey.warnings.push_back(at + "mtllib names no file");
            for (std::size_t w = 1; w < words.size(); ++w) remember(survey.libraries, words[w], number);
        } else if (keyword == "usemtl" && words.size() >= 2) {
            remember(survey.materials, words[1], number);
        }
    });
    for (std::size_t kind = 0; kind < 3; ++kind) {
        for (const BadNumber& b : bad[kind]) {  // a face using one would have thrown
            survey.warnings.push_back(name + ":" + std::to_string(b.line) + ": " + kKindName[kind] + " " + std::to_string(b.index + 1) +
                                      " is " + b.problem + "; no face uses it");
        }
    }
    return survey;
}

}  // namespace raster::detail
