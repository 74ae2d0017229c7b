// A PLY body walked once, element by element, in either binary order or ASCII; stays whole so that
// the three encodings' walks and their one set of checks read side by side.
#include "io/ply/ply_body.hpp"

#include "io/ply/ply_values.hpp"
#include "io/ply/vertex_slots.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/obj_file.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace raster::detail {
namespace {

// A number the file wrote, for a message: shortest form, whole numbers without a point, NaN as nan.
std::string number_text(double value) {
    std::array<char, 32> text{};
    const std::to_chars_result written = std::to_chars(text.data(), text.data() + text.size(), value);
    return std::string(text.data(), written.ptr);
}

bool fixed_size(const PlyElement& element) {
    return std::none_of(element.properties.begin(), element.properties.end(),
                        [](const PlyProperty& p) { return p.list; });
}

class BodyReader {
public:
    BodyReader(const PlyLayout& layout, PlyBytes& bytes, const std::string& name)
        : layout_(layout), bytes_(bytes), name_(name), ascii_(layout.encoding == PlyEncoding::ascii),
          big_(layout.encoding == PlyEncoding::big_endian), line_(layout.header_lines) {}

    PlyBody read() {
        bool vertices_seen = false;
        for (const PlyElement& element : layout_.elements) {
            if (element.count > bytes_.left() / ply_least_bytes(element, ascii_)) {
                throw std::runtime_error(name_ + ": the PLY header declares " + std::to_string(element.count) + " '" +
                                         element.name + "' elements, more than the " + std::to_string(bytes_.left()) +
                                         " bytes left can hold: the file is cut short, or its header is wrong");
            }
            const bool vertices = element.name == "vertex";
            const int corners = element.name == "face" ? ply_corner_list(element) : -1;
            if (element.name == "face" && element.count > 0 && !vertices_seen)
                throw std::runtime_error(name_ +
                                         ": the PLY's faces come before its vertices, which raster does not read");
            if (vertices) {
                vertices_seen = true;
                body_.declared_vertices = element.count;
                slots_ = VertexSlots(element, faces_follow(element));
                slots_.reserve(body_, element.count);
            }
            if (corners >= 0) body_.face_starts.reserve(element.count);
            walk(element, vertices, corners);
            if (!body_.cut_short.empty()) break;
        }
        return std::move(body_);
    }

private:
    // Whether a face element with corners follows the vertices: then they keep their places.
    bool faces_follow(const PlyElement& vertices) const {
        bool after = false;
        for (const PlyElement& element : layout_.elements) {
            if (after && element.name == "face" && element.count > 0 && ply_corner_list(element) >= 0) return true;
            after = after || &element == &vertices;
        }
        return false;
    }

    [[noreturn]] void fail(const std::string& what, std::uint64_t byte) const {
        if (ascii_) throw std::runtime_error(name_ + ":" + std::to_string(line_) + ": " + what);
        throw std::runtime_error(name_ + ": " + what + " (byte " + std::to_string(byte) + ")");
    }

    // Messages the counts check gave before this reader, worded as they were.
    [[noreturn]] void fail_as_before(const std::string& what) const { throw std::runtime_error(name_ + ": " + what); }

    void cut_short(const PlyElement& element, std::uint64_t item) {
        body_.cut_short = "the PLY data is cut short: its header declares " + std::to_string(element.count) + " '" +
                          element.name + "' elements and the data ends in element " + std::to_string(item + 1);
    }

    void walk(const PlyElement& element, bool vertices, int corners) {
        if (!ascii_ && fixed_size(element)) return walk_records(element, vertices);
        for (std::uint64_t i = 0; i < element.count; ++i) {
            const std::size_t faces = body_.face_starts.size(), corners_read = body_.corners.size();
            if (!(ascii_ ? item_text(element, i, vertices, corners) : item_binary(element, i, vertices, corners))) {
                body_.face_starts.resize(faces);  // a face cut short is not drawn
                body_.corners.resize(corners_read);
                cut_short(element, i);
                return;
            }
        }
    }

    // Binary elements of one size (a cloud's vertices), decoded a block at a time.
    void walk_records(const PlyElement& element, bool vertices) {
        std::vector<std::size_t> offsets;
        std::size_t record = 0;
        for (const PlyProperty& p : element.properties) {
            offsets.push_back(record);
            record += static_cast<std::size_t>(ply_type_bytes(p.type));
        }
        if (record == 0) return;  // items of no properties take no bytes
        const bool plain = vertices && slots_.plain(big_);
        for (std::uint64_t i = 0; i < element.count;) {
            const std::span<const std::uint8_t> held = bytes_.ahead(record);
            const std::uint64_t whole = std::min<std::uint64_t>(held.size() / record, element.count - i);
            if (whole == 0) return cut_short(element, i);
            if (plain) {
                for (std::uint64_t k = 0; k < whole; ++k)
                    slots_.keep_plain(held.data() + k * record, offsets.data(), body_);
            } else if (vertices) {
                for (std::uint64_t k = 0; k < whole; ++k) {
                    const std::uint8_t* at_record = held.data() + k * record;
                    slots_.keep(
                        [&](std::size_t p) {
                            return ply_binary_value(at_record + offsets[p], element.properties[p].type, big_);
                        },
                        body_);
                }
            }
            bytes_.advance(static_cast<std::size_t>(whole * record));
            i += whole;
        }
    }

    // One binary item with lists; false where the data ends within it.
    bool item_binary(const PlyElement& element, std::uint64_t i, bool vertices, int corners) {
        const std::uint64_t start = bytes_.offset();
        values_.assign(element.properties.size(), 0.0);
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
            const PlyProperty& p = element.properties[k];
            const auto size = static_cast<std::size_t>(ply_type_bytes(p.list ? p.count_type : p.type));
            const std::span<const std::uint8_t> held = bytes_.ahead(size);
            if (held.size() < size) return false;
            const double value = ply_binary_value(held.data(), p.list ? p.count_type : p.type, big_);
            bytes_.advance(size);
            if (!p.list) {
                values_[k] = value;
                continue;
            }
            const auto entry = static_cast<std::uint64_t>(ply_type_bytes(p.type));
            check_length(element, i, value, start);
            if (value < 0.0 || value > static_cast<double>(bytes_.left() / entry)) {
                fail_as_before("'" + element.name + "' item " + std::to_string(i + 1) + " has a list of " +
                               (value < 0.0 ? std::string("negative length") : number_text(value) + " entries") +
                               ", more than the bytes left can hold");
            }
            const auto length = static_cast<std::uint64_t>(value);
            if (static_cast<int>(k) == corners) {
                begin_face(length, i, start);
                const std::span<const std::uint8_t> entries = bytes_.ahead(static_cast<std::size_t>(length * entry));
                if (entries.size() < length * entry) return false;
                for (std::uint64_t c = 0; c < length; ++c)
                    add_corner(ply_binary_value(entries.data() + c * entry, p.type, big_), i, start);
                bytes_.advance(static_cast<std::size_t>(length * entry));
                continue;
            }
            for (std::uint64_t skip = length * entry; skip > 0;) {  // a list nobody reads
                const std::span<const std::uint8_t> held_list = bytes_.ahead(1);
                if (held_list.empty()) return false;
                const auto step = static_cast<std::size_t>(std::min<std::uint64_t>(skip, held_list.size()));
                bytes_.advance(step);
                skip -= step;
            }
        }
        if (vertices) slots_.keep([&](std::size_t p) { return values_[p]; }, body_);
        return true;
    }

    // One ASCII line; false where the data ends before it, or within it on a last line cut short.
    bool item_text(const PlyElement& element, std::uint64_t i, bool vertices, int corners) {
        std::string_view line;
        bool ended = false;
        if (!bytes_.line(line, ended)) return false;
        ++line_;
        values_.assign(element.properties.size(), 0.0);
        for (std::size_t k = 0; k < element.properties.size(); ++k) {
            const PlyProperty& p = element.properties[k];
            const std::string_view word = ply_next_word(line);
            if (word.empty()) {
                if (!ended) return false;
                if (p.list) continue;  // no length written: an empty list, as assimp reads it
                fail("'" + element.name + "' item " + std::to_string(i + 1) + " has fewer values than its " +
                         std::to_string(element.properties.size()) + " properties",
                     0);
            }
            double value = 0.0;
            if (!ply_text_value(word, p.list ? p.count_type : p.type, value)) {
                if (!ended && line.empty()) return false;  // a number cut short at the end of the data
                fail("'" + printable(word, 40) + "' is not a number of the type '" + element.name + "' property '" +
                         p.name + "' has",
                     0);
            }
            if (!p.list) {
                values_[k] = value;
                continue;
            }
            check_length(element, i, value, 0);
            if (value < 0.0 || value > static_cast<double>(line.size() / 2 + 1)) {
                fail_as_before("'" + element.name + "' item " + std::to_string(i + 1) +
                               " has a list longer than its line");
            }
            const auto length = static_cast<std::uint64_t>(value);
            const bool kept = static_cast<int>(k) == corners;
            if (kept) begin_face(length, i, 0);
            for (std::uint64_t c = 0; c < length; ++c) {
                const std::string_view entry = ply_next_word(line);
                double index = 0.0;
                if (entry.empty()) {
                    if (!ended) return false;
                    fail_as_before("'" + element.name + "' item " + std::to_string(i + 1) +
                                   " has a list longer than its line");
                }
                if (!ply_text_value(entry, p.type, index)) {
                    if (!ended && line.empty()) return false;
                    fail("'" + printable(entry, 40) + "' is not a number of the type '" + element.name +
                             "' property '" + p.name + "' has",
                         0);
                }
                if (kept) add_corner(index, i, 0);
            }
        }
        if (vertices) slots_.keep([&](std::size_t p) { return values_[p]; }, body_);
        return true;
    }

    // A list's length of a float type must still be a whole number: NaN or 2.5 is none.
    void check_length(const PlyElement& element, std::uint64_t i, double value, std::uint64_t start) const {
        if (std::isnan(value) || (value > 0.0 && value != std::floor(value))) {
            fail("'" + element.name + "' item " + std::to_string(i + 1) + " has a list whose length " +
                     number_text(value) + " is not a whole number",
                 start);
        }
    }

    void begin_face(std::uint64_t corners, std::uint64_t i, std::uint64_t start) {
        if (corners > kMaxFaceCorners)
            fail("a face of more than " + std::to_string(kMaxFaceCorners) + " corners", start);
        if (corners == 0) fail("face " + std::to_string(i + 1) + " has no corners", start);
        body_.face_starts.push_back(body_.corners.size());
    }

    void add_corner(double index, std::uint64_t i, std::uint64_t start) {
        if (!(index >= 0.0 && index < static_cast<double>(body_.declared_vertices)) || index != std::floor(index)) {
            fail("face " + std::to_string(i + 1) + " names vertex " + number_text(index) + ", but the PLY has " +
                     std::to_string(body_.declared_vertices) + " vertices (counting from 0)",
                 start);
        }
        body_.corners.push_back(static_cast<std::uint32_t>(index));
    }

    const PlyLayout& layout_;
    PlyBytes& bytes_;
    const std::string& name_;
    const bool ascii_, big_;
    std::uint64_t line_;
    PlyBody body_;
    VertexSlots slots_;
    std::vector<double> values_;
};

}  // namespace

PlyBody read_ply_body(const PlyLayout& layout, PlyBytes& bytes, const std::string& name) {
    return BodyReader(layout, bytes, name).read();
}

}  // namespace raster::detail
