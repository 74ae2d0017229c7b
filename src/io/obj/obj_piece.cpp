// Stays whole: one pass over a range's lines, every statement checked as it is read.
#include "io/obj/obj_piece.hpp"

#include "io/obj/obj_lines.hpp"

#include <raster/image/colour.hpp>
#include <raster/io/input_file.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace raster::detail {

namespace {

// How many numbers of each kind must be there (a texture coordinate may give u alone); vt's
// third, like v's colours, is not a coordinate raster uses.
constexpr std::array<std::size_t, 3> kNeededNumbers = {3, 1, 3};
constexpr float kNotANumber = std::numeric_limits<float>::quiet_NaN();

// A word as from_chars reads it: a leading '+' dropped, as C's strtod takes it.
std::string_view without_plus(std::string_view word) {
    if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
    return word;
}

// Why a word is not a finite coordinate that a float holds, or "" when it is one (a number too
// small for a float is read as 0, as written).
std::string number_problem(std::string_view word) {
    const std::string quoted = "'" + printable(word, 40) + "'";
    const std::string_view digits = without_plus(word);
    double value = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (end != digits.data() + digits.size() || (error != std::errc() && error != std::errc::result_out_of_range)) {
        return quoted + ", which is not a number";
    }
    if (error == std::errc::result_out_of_range) {
        const std::string copy(digits);
        value = std::strtod(copy.c_str(), nullptr);  // tells overflow (huge) from underflow (tiny)
        if (std::abs(value) <= 1.0) return "";
    }
    if (!std::isfinite(value)) return quoted + ", which is not a finite number";
    if (std::abs(value) > std::numeric_limits<float>::max())
        return quoted + ", which is beyond the largest coordinate raster stores";
    return "";
}

// A coordinate read into `value`; false, with the reason in `problem`, for a word that is not one.
bool read_coordinate(std::string_view word, float& value, std::string& problem) {
    const std::string_view digits = without_plus(word);
    double read = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), read);
    if (error == std::errc() && end == digits.data() + digits.size() &&
        std::abs(read) <= std::numeric_limits<float>::max()) {
        value = static_cast<float>(read);
        return true;
    }
    problem = number_problem(word);
    if (!problem.empty()) return false;
    value = static_cast<float>(std::strtod(std::string(digits).c_str(), nullptr));  // too small: 0 or near it
    return true;
}

// A colour channel (sRGB, as MeshLab and others write it) in linear light, clamped to [0, 1],
// white where it is not finite (doc/conventions.md#vertex-colours); false for a word that is no number.
bool read_channel(std::string_view word, float& linear) {
    const std::string_view digits = without_plus(word);
    double read = 0.0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), read);
    if (end != digits.data() + digits.size() || (error != std::errc() && error != std::errc::result_out_of_range))
        return false;
    if (error != std::errc()) read = std::strtod(std::string(digits).c_str(), nullptr);  // huge or tiny
    const double c = std::isfinite(read) ? std::clamp(read, 0.0, 1.0) : 1.0;
    linear = static_cast<float>(linear_from_srgb_channel(static_cast<double>(static_cast<float>(c))));
    return true;
}

std::size_t count_words(std::string_view text) {
    Words words(text);
    std::size_t count = 0;
    while (!words.next().empty()) ++count;
    return count;
}

// The reader of one range: its state between lines.
class RangeReader {
public:
    RangeReader(const ObjRange& range, const std::string& name, std::size_t max_corners, std::size_t max_line_bytes,
                const BadNumbers* earlier_bad)
        : range_(range), name_(name), max_corners_(max_corners), max_line_bytes_(max_line_bytes),
          earlier_bad_(earlier_bad) {}

    ObjPiece read() {
        TextLines lines(range_.text);
        for (std::string_view line; lines.next(line);) {
            ++piece_.counts.lines;
            line_ = range_.before.lines + piece_.counts.lines;
            if (line.size() > max_line_bytes_) {
                fail("a line longer than " + std::to_string((max_line_bytes_ + (1U << 20) - 1) >> 20) +
                     " MiB, the most raster reads in one line");
            }
            if (range_.first && piece_.counts.lines == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
            std::string_view rest;
            switch (statement_of(line, rest)) {
            case ObjStatement::position: position(rest); break;
            case ObjStatement::uv: uv(rest); break;
            case ObjStatement::normal: normal(rest); break;
            case ObjStatement::face: face(rest); break;
            case ObjStatement::point: point(rest); break;
            case ObjStatement::line: segments(rest); break;
            case ObjStatement::library: library(rest); break;
            case ObjStatement::material: material(rest); break;
            case ObjStatement::other: break;
            }
        }
        return std::move(piece_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw std::runtime_error(name_ + ":" + std::to_string(line_) + ": " + problem);
    }

    // The numbers of a v, vt or vn: false, with the first problem noted, when one is not usable.
    template <std::size_t Count>
    bool numbers(ObjKind kind, Words& words, std::array<float, Count>& values) {
        std::string problem;
        std::size_t given = 0;
        for (std::string_view word; given < Count && !(word = words.next()).empty(); ++given) {
            if (problem.empty()) (void)read_coordinate(word, values[given], problem);
        }
        if (problem.empty() && given < kNeededNumbers[kind]) {
            problem =
                "only " + std::to_string(given) + " of its " + std::to_string(kNeededNumbers[kind]) + " coordinates";
        }
        const std::size_t index = range_.before.defined[kind] + piece_.counts.defined[kind]++;
        if (index >= kMaxSoupVertices)
            fail("more " + std::string(kObjKindPlurals[kind]) + " than raster counts in 32 bits");
        if (problem.empty()) return true;
        piece_.bad[kind].push_back({index, line_, std::move(problem)});
        return false;
    }

    void position(std::string_view rest) {
        Words words(rest);
        std::array<float, 3> xyz{};
        if (!numbers(kObjPosition, words, xyz)) xyz.fill(kNotANumber);
        piece_.positions.emplace_back(xyz[0], xyz[1], -xyz[2]);
        LinearRgb colour{};
        const std::string_view r = words.next(), g = words.next(), b = words.next();
        const bool coloured =
            !b.empty() && read_channel(r, colour.r) && read_channel(g, colour.g) && read_channel(b, colour.b);
        if (!coloured) return;
        // OBJ's colours are all or none: kept while every vertex so far gives one.
        if (piece_.coloured_vertices++ + 1 == piece_.positions.size()) piece_.colours.push_back(colour);
    }

    void uv(std::string_view rest) {
        Words words(rest);
        std::array<float, 2> uv{};
        if (!numbers(kObjUv, words, uv)) uv.fill(kNotANumber);
        piece_.uvs.emplace_back(uv[0], uv[1]);
    }

    void normal(std::string_view rest) {
        Words words(rest);
        std::array<float, 3> xyz{};
        if (!numbers(kObjNormal, words, xyz)) xyz.fill(kNotANumber);
        piece_.normals.emplace_back(xyz[0], xyz[1], -xyz[2]);
    }

    // Whether the value of that kind at that index (from 0, over the file) was read as NaN:
    // looked up here when this range holds it, else in `earlier_bad`, else left for later.
    void check_number(ObjKind kind, std::size_t index, const char* statement) {
        const std::size_t first = range_.before.defined[kind];
        const BadNumbers* bad = &piece_.bad;
        if (index >= first) {
            const std::size_t local = index - first;
            const bool nan = kind == kObjPosition ? std::isnan(piece_.positions[local].x)
                             : kind == kObjUv     ? std::isnan(piece_.uvs[local].x)
                                                  : std::isnan(piece_.normals[local].x);
            if (!nan) return;
        } else if (earlier_bad_ != nullptr) {
            bad = earlier_bad_;
        } else {
            piece_.names_earlier = true;
            return;
        }
        const auto& list = (*bad)[kind];
        const auto found = std::lower_bound(list.begin(), list.end(), index,
                                            [](const BadNumber& b, std::size_t i) { return b.index < i; });
        if (found == list.end() || found->index != index) return;
        fail(std::string("the ") + statement + " uses " + kObjKindNames[kind] + " " + std::to_string(index + 1) +
             ", but line " + std::to_string(found->line) + " gives it " + found->problem);
    }

    // One index of a corner, OBJ's way: 1 is the first defined so far, -1 the last one.
    std::size_t resolved_index(std::string_view text, ObjKind kind, const char* statement) const {
        const std::string what = kObjKindNames[kind];
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size())
            fail("'" + printable(text, 40) + "' is not a " + what + " index");
        if (value == 0) fail(what + " index 0: OBJ counts from 1");
        const std::size_t defined = range_.before.defined[kind] + piece_.counts.defined[kind];
        const long long resolved = value > 0 ? value : static_cast<long long>(defined) + value + 1;
        if (resolved < 1 || resolved > static_cast<long long>(defined)) {
            fail(std::string(statement) + " names " + what + " " + std::to_string(value) + ", but " +
                 std::to_string(defined) + (defined == 1 ? " is" : " are") + " defined before it");
        }
        return static_cast<std::size_t>(resolved - 1);
    }

    // A corner of a face, or a vertex of a point or line: v, v/vt, v/vt/vn or v//vn.
    ObjCorner corner_of(std::string_view word, const char* statement, std::string_view rest) {
        std::array<std::string_view, 3> fields{};
        std::size_t count = 0;
        for (std::size_t start = 0; count < 3; ++count) {
            const std::size_t slash = word.find('/', start);
            fields[count] =
                word.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        const bool face = statement[0] == 'f';
        // A face with too many corners is refused before any of its corners.
        const auto refuse = [&](const std::string& problem) {
            if (face && count_words(rest) > max_corners_) too_many_corners();
            fail(problem);
        };
        const bool well_formed =
            count < 3 && !fields[0].empty() && (count != 1 || !fields[1].empty()) && (count != 2 || !fields[2].empty());
        if (!well_formed) {
            refuse(std::string(face ? "corner '" : "vertex '") + printable(word, 40) +
                   "' is not of the form v, v/vt, v/vt/vn or v//vn");
        }
        ObjCorner corner;
        for (std::size_t k = 0; k <= count; ++k) {
            if (fields[k].empty()) continue;  // v//vn
            const auto kind = static_cast<ObjKind>(k);
            std::size_t index = 0;
            try {
                index = resolved_index(fields[k], kind, statement);
                check_number(kind, index, statement);
            } catch (const std::runtime_error&) {
                if (face && count_words(rest) > max_corners_) too_many_corners();
                throw;
            }
            const auto at = static_cast<std::uint32_t>(index);
            (kind == kObjPosition ? corner.position : kind == kObjUv ? corner.uv : corner.normal) = at;
        }
        return corner;
    }

    [[noreturn]] void too_many_corners() const {
        fail("a face of more than " + std::to_string(max_corners_) + " corners");
    }

    void face(std::string_view rest) {
        Words words(rest);
        corners_.clear();
        for (std::string_view word; !(word = words.next()).empty();) {
            if (corners_.size() == max_corners_) too_many_corners();
            corners_.push_back(corner_of(word, "face", rest));
        }
        if (corners_.size() < 3) {
            ++piece_.skipped_faces;
            return;
        }
        ++piece_.faces;
        if (earlier_bad_ != nullptr) return;  // only checking
        // Each piece turned from OBJ's counter-clockwise order to raster's clockwise one.
        if (corners_.size() == 3) {
            piece_.triangles.push_back({{corners_[0], corners_[2], corners_[1]}, material_});
            return;
        }
        piece_.polygons.push_back({piece_.triangles.size(), piece_.polygon_corners.size(), corners_.size()});
        piece_.polygon_corners.insert(piece_.polygon_corners.end(), corners_.begin(), corners_.end());
        piece_.triangles.resize(piece_.triangles.size() + corners_.size() - 2, {{}, material_});
    }

    void point(std::string_view rest) {
        Words words(rest);
        for (std::string_view word; !(word = words.next()).empty();) {
            const ObjCorner corner = corner_of(word, "point", rest);
            if (earlier_bad_ == nullptr) piece_.points.push_back(corner);
        }
    }

    void segments(std::string_view rest) {
        Words words(rest);
        std::size_t count = 0;
        ObjCorner previous;
        for (std::string_view word; !(word = words.next()).empty(); ++count) {
            const ObjCorner corner = corner_of(word, "line", rest);
            if (count > 0 && earlier_bad_ == nullptr) piece_.segments.push_back({previous, corner});
            previous = corner;
        }
        if (count < 2 && piece_.short_line == 0) piece_.short_line = line_;
        piece_.segment_count += count < 2 ? 0 : count - 1;
    }

    // mtllib's files, split at spaces and tabs; a backslash keeps the character after it.
    void library(std::string_view rest) {
        MaterialStatement statement{true, {}, line_};
        std::string name;
        bool escaped = false;
        for (const char c : rest) {
            if (!escaped && c == '\\') {
                escaped = true;
                continue;
            }
            if (!escaped && (c == ' ' || c == '\t')) {
                if (!name.empty()) statement.names.push_back(std::move(name));
                name.clear();
            } else {
                name += c;
            }
            escaped = false;
        }
        if (!name.empty()) statement.names.push_back(std::move(name));
        if (statement.names.empty() && piece_.empty_libraries++ == 0) piece_.empty_library_line = line_;
        piece_.materials.push_back(std::move(statement));
    }

    // usemtl and no name: a material without a name, if a library has one, else the default.
    void material(std::string_view rest) {
        Words words(rest);
        MaterialStatement statement{false, {}, line_};
        if (const std::string_view name = words.next(); !name.empty()) statement.names.emplace_back(name);
        material_ = static_cast<int>(piece_.materials.size());
        piece_.materials.push_back(std::move(statement));
    }

    const ObjRange& range_;
    const std::string& name_;
    std::size_t max_corners_;
    std::size_t max_line_bytes_;
    const BadNumbers* earlier_bad_;
    ObjPiece piece_;
    std::size_t line_ = 0;
    int material_ = -1;
    std::vector<ObjCorner> corners_;
};

}  // namespace

ObjCounts count_obj_range(std::string_view text, bool first) {
    ObjCounts counts;
    TextLines lines(text);
    for (std::string_view line; lines.next(line);) {
        if (++counts.lines == 1 && first && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
        std::string_view rest;
        const ObjStatement statement = statement_of(line, rest);
        if (statement == ObjStatement::position) ++counts.defined[kObjPosition];
        if (statement == ObjStatement::uv) ++counts.defined[kObjUv];
        if (statement == ObjStatement::normal) ++counts.defined[kObjNormal];
    }
    return counts;
}

ObjPiece read_obj_range(const ObjRange& range, const std::string& name, std::size_t max_corners,
                        std::size_t max_line_bytes, const BadNumbers* earlier_bad) {
    return RangeReader(range, name, max_corners, max_line_bytes, earlier_bad).read();
}

}  // namespace raster::detail
