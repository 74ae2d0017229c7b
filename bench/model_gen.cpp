// model-gen: the big models of tools/bench-big-models.sh, written on demand rather than committed:
// a height-field grid, a wavy sphere or a coloured point cloud of a given size, as OBJ, binary PLY
// or binary STL (doc/performance.md#big-models-bench).
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Vertex {
    float x, y, z;
    std::array<std::uint8_t, 3> colour;
};

struct Shape {
    std::vector<Vertex> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // counting from 0, counter-clockwise from outside
};

// A columns x rows height field over [-1, 1] x [-0.5, 0.5], two triangles a cell.
Shape grid(std::size_t triangles) {
    const auto columns =
        static_cast<std::uint32_t>(std::max(1.0, std::round(std::sqrt(static_cast<double>(triangles)))));
    const std::uint32_t rows = std::max(columns / 2, 1U);
    Shape shape;
    for (std::uint32_t j = 0; j <= rows; ++j) {
        for (std::uint32_t i = 0; i <= columns; ++i) {
            const double x = 2.0 * i / columns - 1.0, y = static_cast<double>(j) / rows - 0.5;
            shape.vertices.push_back({static_cast<float>(x),
                                      static_cast<float>(y),
                                      static_cast<float>(0.05 * std::sin(i * 0.05) * std::cos(j * 0.07)),
                                      {}});
        }
    }
    for (std::uint32_t j = 0; j < rows; ++j) {
        for (std::uint32_t i = 0; i < columns; ++i) {
            const std::uint32_t a = j * (columns + 1) + i, b = a + 1, c = a + columns + 1, d = c + 1;
            shape.triangles.push_back({a, b, d});
            shape.triangles.push_back({a, d, c});
        }
    }
    return shape;
}

// A sphere of radius about 1 with waves of 5 %, in rings round y: two triangles a cell, closed.
Shape sphere(std::size_t triangles) {
    const auto rings =
        static_cast<std::uint32_t>(std::max(2.0, std::round(std::sqrt(static_cast<double>(triangles) / 4.0))));
    const std::uint32_t around = 2 * rings;
    Shape shape;
    for (std::uint32_t j = 0; j <= rings; ++j) {
        const double theta = std::numbers::pi * j / rings;
        for (std::uint32_t i = 0; i < around; ++i) {
            const double phi = 2.0 * std::numbers::pi * i / around;
            const double r = 1.0 + 0.05 * std::sin(8.0 * theta) * std::cos(8.0 * phi);
            shape.vertices.push_back({static_cast<float>(r * std::sin(theta) * std::cos(phi)),
                                      static_cast<float>(r * std::cos(theta)),
                                      static_cast<float>(r * std::sin(theta) * std::sin(phi)),
                                      {}});
        }
    }
    for (std::uint32_t j = 0; j < rings; ++j) {
        for (std::uint32_t i = 0; i < around; ++i) {
            const std::uint32_t a = j * around + i, b = j * around + (i + 1) % around, c = a + around, d = b + around;
            shape.triangles.push_back({a, c, d});
            shape.triangles.push_back({a, d, b});
        }
    }
    return shape;
}

// Points spread evenly over the unit sphere (a Fibonacci lattice), coloured by where they are.
Shape cloud(std::size_t points) {
    Shape shape;
    const double turn = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < points; ++i) {
        const double y = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(points);
        const double r = std::sqrt(1.0 - y * y), a = turn * static_cast<double>(i);
        const auto byte = [](double v) { return static_cast<std::uint8_t>(std::clamp(127.5 + 127.5 * v, 0.0, 255.0)); };
        shape.vertices.push_back({static_cast<float>(r * std::cos(a)),
                                  static_cast<float>(y),
                                  static_cast<float>(r * std::sin(a)),
                                  {byte(r * std::cos(a)), byte(y), byte(r * std::sin(a))}});
    }
    return shape;
}

template <typename T>
void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // little-endian machines only, as the PLY header says
    out.append(bytes, sizeof(T));
}

void put_number(std::string& out, double value) {
    std::array<char, 32> text{};
    const auto written = std::to_chars(text.data(), text.data() + text.size(), static_cast<float>(value));
    out.append(text.data(), written.ptr);
}

std::string obj_of(const Shape& shape) {
    std::string out;
    for (const Vertex& v : shape.vertices) {
        out += "v ";
        put_number(out, v.x), out += ' ', put_number(out, v.y), out += ' ', put_number(out, v.z), out += '\n';
    }
    for (const auto& t : shape.triangles) {
        out += "f " + std::to_string(t[0] + 1) + ' ' + std::to_string(t[1] + 1) + ' ' + std::to_string(t[2] + 1) + '\n';
    }
    if (shape.triangles.empty()) out += "# a point cloud: vertices alone\n";
    return out;
}

std::string ply_of(const Shape& shape) {
    const bool points = shape.triangles.empty();
    std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(shape.vertices.size()) +
                      "\nproperty float x\nproperty float y\nproperty float z\n";
    if (points) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (!points)
        out += "element face " + std::to_string(shape.triangles.size()) + "\nproperty list uchar int vertex_indices\n";
    out += "end_header\n";
    for (const Vertex& v : shape.vertices) {
        put(out, v.x), put(out, v.y), put(out, v.z);
        if (points) out.append(reinterpret_cast<const char*>(v.colour.data()), 3);
    }
    for (const auto& t : shape.triangles) {
        put(out, std::uint8_t{3});
        for (const std::uint32_t i : t) put(out, static_cast<std::int32_t>(i));
    }
    return out;
}

std::string stl_of(const Shape& shape) {
    if (shape.triangles.empty()) throw std::invalid_argument("an STL holds triangles, not a point cloud");
    std::string out(80, '\0');
    out.replace(0, 22, "raster model-gen shape");
    put(out, static_cast<std::uint32_t>(shape.triangles.size()));
    for (const auto& t : shape.triangles) {
        for (int k = 0; k < 3; ++k) put(out, 0.0F);  // no normal: readers take the corners'
        for (const std::uint32_t i : t)
            put(out, shape.vertices[i].x), put(out, shape.vertices[i].y), put(out, shape.vertices[i].z);
        put(out, std::uint16_t{0});
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    const bool help = argc == 2 && std::strcmp(argv[1], "--help") == 0;
    if (argc != 4) {
        std::fputs("usage: model-gen grid|sphere|cloud COUNT FILE.obj|.ply|.stl\n"
                   "  COUNT triangles (grid, sphere) or points (cloud), up to 100000000; FILE must not exist\n",
                   help ? stdout : stderr);
        return help ? 0 : 2;
    }
    std::filesystem::path partial;  // removed if anything fails once it is written
    try {
        const std::string kind = argv[1];
        const std::filesystem::path file = argv[3];
        std::size_t count = 0;
        const std::string_view written = argv[2];
        const auto parsed = std::from_chars(written.data(), written.data() + written.size(), count);
        if (parsed.ec != std::errc() || parsed.ptr != written.data() + written.size() || count < 2 || count > 100000000)
            throw std::invalid_argument("COUNT must be a whole number from 2 to 100000000, got '" +
                                        std::string(written) + "'");
        if (std::filesystem::exists(file)) throw std::invalid_argument(file.string() + " exists; remove it first");
        const Shape shape = kind == "grid"     ? grid(count)
                            : kind == "sphere" ? sphere(count)
                            : kind == "cloud"
                                ? cloud(count)
                                : throw std::invalid_argument("no shape '" + kind + "': grid, sphere or cloud");
        const std::string extension = file.extension().string();
        const std::string bytes = extension == ".obj"   ? obj_of(shape)
                                  : extension == ".ply" ? ply_of(shape)
                                  : extension == ".stl"
                                      ? stl_of(shape)
                                      : throw std::invalid_argument("FILE must end in .obj, .ply or .stl");
        partial = file.string() + ".partial";  // linked into place once whole: never over a file
        std::ofstream(partial, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (std::filesystem::file_size(partial) != bytes.size())
            throw std::runtime_error("could not write " + partial.string());
        std::filesystem::create_hard_link(partial, file);
        std::filesystem::remove(partial);
        std::printf("%s: %zu vertices, %zu triangles, %zu bytes\n", file.c_str(), shape.vertices.size(),
                    shape.triangles.size(), bytes.size());
    } catch (const std::exception& problem) {
        std::error_code ignored;
        if (!partial.empty()) std::filesystem::remove(partial, ignored);
        std::fprintf(stderr, "model-gen: %s\n", problem.what());
        return 1;
    }
    return 0;
}
