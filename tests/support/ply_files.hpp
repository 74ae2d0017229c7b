#pragma once

#include <string>
#include <vector>

// PLY files written by tests, in any encoding and with any property types.
namespace test_support {

struct PlyColumn {
    std::string type;  // "float", "uchar", "int16", ...
    std::string name;
};

struct PlySpec {
    std::string format = "ascii";  // or binary_little_endian, binary_big_endian
    std::vector<PlyColumn> vertex;
    std::vector<std::vector<double>> vertices;
    std::string face_list = "uchar int";  // the list's count and index types; "" for no face element
    std::vector<std::vector<long long>> faces;
    // An element of its own between the vertices and the faces: a header block and its body as written.
    std::string between_header;
    std::string between_body;
};

// One value of a PLY type, as ASCII text (with a space after it) or bytes in either order.
std::string ply_value(const std::string& type, double value, const std::string& format);

[[nodiscard]] std::string ply_text(const PlySpec& spec);

}  // namespace test_support
