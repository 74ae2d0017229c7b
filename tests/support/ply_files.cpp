#include "support/ply_files.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace test_support {
namespace {

template <typename T>
std::string bytes_of(T value, bool big) {
    std::string out(sizeof(T), '\0');
    std::memcpy(out.data(), &value, sizeof(T));
    if (big == (std::endian::native == std::endian::little)) {
        for (std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(out[k], out[sizeof(T) - 1 - k]);
    }
    return out;
}

}  // namespace

std::string ply_value(const std::string& type, double value, const std::string& format) {
    if (format == "ascii") {
        std::ostringstream text;
        text.precision(17);
        if (type == "float" || type == "float32") {
            text.precision(9);
            text << static_cast<float>(value);
        } else if (type == "double" || type == "float64") {
            text << value;
        } else {
            text << static_cast<long long>(value);
        }
        return text.str() + " ";
    }
    const bool big = format == "binary_big_endian";
    if (type == "char" || type == "int8") return bytes_of(static_cast<std::int8_t>(value), big);
    if (type == "uchar" || type == "uint8") return bytes_of(static_cast<std::uint8_t>(value), big);
    if (type == "short" || type == "int16") return bytes_of(static_cast<std::int16_t>(value), big);
    if (type == "ushort" || type == "uint16") return bytes_of(static_cast<std::uint16_t>(value), big);
    if (type == "int" || type == "int32") return bytes_of(static_cast<std::int32_t>(value), big);
    if (type == "uint" || type == "uint32") return bytes_of(static_cast<std::uint32_t>(value), big);
    if (type == "double" || type == "float64") return bytes_of(value, big);
    return bytes_of(static_cast<float>(value), big);
}

std::string ply_text(const PlySpec& spec) {
    std::string out = "ply\nformat " + spec.format + " 1.0\ncomment written by a test\nelement vertex " +
                      std::to_string(spec.vertices.size()) + "\n";
    for (const PlyColumn& column : spec.vertex) out += "property " + column.type + " " + column.name + "\n";
    out += spec.between_header;
    const std::string count_type = spec.face_list.substr(0, spec.face_list.find(' '));
    const std::string index_type = spec.face_list.substr(spec.face_list.find(' ') + 1);
    if (!spec.face_list.empty()) {
        out += "element face " + std::to_string(spec.faces.size()) + "\nproperty list " + spec.face_list +
               " vertex_indices\n";
    }
    out += "end_header\n";
    const bool ascii = spec.format == "ascii";
    for (const std::vector<double>& vertex : spec.vertices) {
        for (std::size_t k = 0; k < vertex.size(); ++k) out += ply_value(spec.vertex[k].type, vertex[k], spec.format);
        if (ascii) out += "\n";
    }
    out += spec.between_body;
    if (spec.face_list.empty()) return out;
    for (const std::vector<long long>& face : spec.faces) {
        out += ply_value(count_type, static_cast<double>(face.size()), spec.format);
        for (const long long index : face) out += ply_value(index_type, static_cast<double>(index), spec.format);
        if (ascii) out += "\n";
    }
    return out;
}

}  // namespace test_support
