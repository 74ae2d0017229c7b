#include "model_files.hpp"

#include "scratch.hpp"

#include <array>
#include <cstdint>
#include <fstream>
#include <vector>

namespace test_support {

namespace {

void put16(std::vector<std::uint8_t>& out, std::uint32_t v) {
    out.push_back(static_cast<std::uint8_t>(v));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    put16(out, v & 0xFFFF);
    put16(out, v >> 16);
}
void put32_big(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xFFFFFFFFU;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320U & (0U - (crc & 1U)));
    }
    return ~crc;
}

void put_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
    put32_big(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    put32_big(out, crc32(out.data() + start, out.size() - start));
}

}  // namespace

void write_bmp(const std::filesystem::path& path, const raster::Framebuffer& image) {
    const auto w = static_cast<std::uint32_t>(image.width()), h = static_cast<std::uint32_t>(image.height());
    const std::uint32_t row = (w * 3 + 3) / 4 * 4;
    std::vector<std::uint8_t> out{'B', 'M'};
    put32(out, 54 + row * h);
    put32(out, 0);
    put32(out, 54);
    put32(out, 40);
    put32(out, w);
    put32(out, h);
    put16(out, 1);
    put16(out, 24);
    for (int i = 0; i < 6; ++i) put32(out, 0);
    for (int y = image.height() - 1; y >= 0; --y) {
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb c = image.pixel(x, y);
            out.insert(out.end(), {c.b, c.g, c.r});
        }
        out.resize(out.size() + (row - w * 3), 0);
    }
    write_bytes(path, out);
}

void write_tga(const std::filesystem::path& path, const raster::Framebuffer& image) {
    std::vector<std::uint8_t> out{0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    put16(out, static_cast<std::uint32_t>(image.width()));
    put16(out, static_cast<std::uint32_t>(image.height()));
    out.push_back(24);
    out.push_back(0x20);  // origin at the top left
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb c = image.pixel(x, y);
            out.insert(out.end(), {c.b, c.g, c.r});
        }
    }
    write_bytes(path, out);
}

void write_png(const std::filesystem::path& path, const raster::Framebuffer& image) {
    std::vector<std::uint8_t> raw;
    for (int y = 0; y < image.height(); ++y) {
        raw.push_back(0);  // no filter
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb c = image.pixel(x, y);
            raw.insert(raw.end(), {c.r, c.g, c.b});
        }
    }
    std::vector<std::uint8_t> zlib{0x78, 0x01};
    for (std::size_t at = 0; at < raw.size() || at == 0; at += 65535) {
        const std::size_t size = std::min<std::size_t>(65535, raw.size() - at);
        zlib.push_back(at + size >= raw.size() ? 1 : 0);
        put16(zlib, static_cast<std::uint32_t>(size));
        put16(zlib, static_cast<std::uint32_t>(~size & 0xFFFF));
        zlib.insert(zlib.end(), raw.begin() + static_cast<std::ptrdiff_t>(at),
                    raw.begin() + static_cast<std::ptrdiff_t>(at + size));
        if (size == 0) break;
    }
    std::uint32_t a = 1, b = 0;
    for (const std::uint8_t byte : raw) a = (a + byte) % 65521, b = (b + a) % 65521;
    put32_big(zlib, (b << 16) | a);
    std::vector<std::uint8_t> header;
    put32_big(header, static_cast<std::uint32_t>(image.width()));
    put32_big(header, static_cast<std::uint32_t>(image.height()));
    header.insert(header.end(), {8, 2, 0, 0, 0});
    std::vector<std::uint8_t> out{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    put_chunk(out, "IHDR", header);
    put_chunk(out, "IDAT", zlib);
    put_chunk(out, "IEND", {});
    write_bytes(path, out);
}

raster::Framebuffer checkerboard(int squares, int texels, raster::Rgb a, raster::Rgb b) {
    raster::Framebuffer image(squares * texels, squares * texels);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) image.set_pixel(x, y, ((x / texels + y / texels) % 2 == 0) ? a : b);
    }
    return image;
}

std::string textured_cube_obj(const std::string& mtllib, const std::string& material) {
    std::string obj = mtllib.empty() ? "" : "mtllib " + mtllib + "\n";
    obj += "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    if (!material.empty()) obj += "usemtl " + material + "\n";
    obj +=
        "f 5/1 6/2 7/3 8/4\nf 2/1 1/2 4/3 3/4\nf 6/1 2/2 3/3 7/4\nf 1/1 5/2 8/3 4/4\nf 8/1 7/2 3/3 4/4\nf 1/1 2/2 6/3 5/4\n";
    return obj;
}

std::filesystem::path write_crate_on_floor(const std::filesystem::path& folder) {
    write_png(folder / "checker.png", checkerboard(4, 8, {230, 190, 60}, {40, 90, 200}));
    write_text(folder / "crate.mtl", "newmtl crate\nKd 1 1 1\nKs 0.25 0.25 0.25\nNs 32\nmap_Kd checker.png\n"
                                     "newmtl floor\nKd 0.3 0.5 0.3\n");
    std::string obj = textured_cube_obj("crate.mtl", "crate");
    obj += "v -3 -1 -3\nv 3 -1 -3\nv 3 -1 3\nv -3 -1 3\nusemtl floor\nf 12 11 10 9\n";
    write_text(folder / "crate.obj", obj);
    return folder / "crate.obj";
}

namespace {

std::string base64(const std::string& bytes) {
    static const char* const kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t group = 0;
        for (std::size_t k = 0; k < 3; ++k)
            group = group << 8 | (i + k < bytes.size() ? static_cast<std::uint8_t>(bytes[i + k]) : 0U);
        for (std::size_t k = 0; k < 4; ++k)
            out += k <= (bytes.size() - i) ? kDigits[(group >> (18 - 6 * k)) & 63U] : '=';
    }
    return out;
}

template <typename Value>
void append_raw(std::string& bytes, Value value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// The tetrahedron's facets, counter-clockwise from outside, as STL and OBJ write them.
const float kTetrahedron[4][3][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}},
                                     {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                                     {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                     {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

}  // namespace

std::string gltf_two_squares() {
    std::string buffer;
    for (const float v : {-1.0F, -1.0F, 0.0F, 1.0F, -1.0F, 0.0F, 1.0F, 1.0F, 0.0F, -1.0F, 1.0F, 0.0F})
        append_raw(buffer, v);
    for (const int i : {0, 1, 2, 0, 2, 3}) append_raw(buffer, static_cast<std::uint16_t>(i));
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"children": [1, 2], "translation": [0, 0.5, 0]},
            {"mesh": 0, "translation": [-1.3, 0, 0]},
            {"mesh": 0, "translation": [1.3, 0, 0], "rotation": [0, 0, 0.3826834, 0.9238795], "scale": [0.5, 0.5, 0.5]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5}}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" +
           base64(buffer) + "\"}]}\n";
}

std::string stl_tetrahedron_ascii() {
    std::string stl = "solid tetrahedron\n";
    for (const auto& facet : kTetrahedron) {
        stl += "  facet normal 0 0 0\n    outer loop\n";
        for (const auto& p : facet)
            stl +=
                "      vertex " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
        stl += "    endloop\n  endfacet\n";
    }
    return stl + "endsolid tetrahedron\n";
}

std::string gltf_coloured_triangle(float red, float green, float blue) {
    std::string buffer;
    for (const float v : {-1.0F, -1.0F, 0.0F, 1.0F, -1.0F, 0.0F, 0.0F, 1.0F, 0.0F}) append_raw(buffer, v);
    for (int corner = 0; corner < 3; ++corner) {
        for (const float v : {red, green, blue}) append_raw(buffer, v);
    }
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}],
  "buffers": [{"byteLength": 72, "uri": "data:application/octet-stream;base64,)" +
           base64(buffer) + "\"}]}\n";
}

std::string stl_tetrahedron_binary(std::array<std::uint16_t, 4> attributes) {
    std::string stl(80, ' ');
    append_raw(stl, std::uint32_t{4});
    std::size_t face = 0;
    for (const auto& facet : kTetrahedron) {
        for (int k = 0; k < 3; ++k) append_raw(stl, 0.0F);  // no normal: made from the corners
        for (const auto& p : facet) {
            for (const float v : p) append_raw(stl, v);
        }
        append_raw(stl, attributes[face++]);
    }
    return stl;
}

std::string ply_pyramid() {
    return "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
           "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 5\nproperty list uchar int vertex_indices\n"
           "end_header\n"
           "-1 0 -1 255 0 0\n1 0 -1 0 255 0\n1 0 1 0 0 255\n-1 0 1 255 255 0\n0 1.5 0 255 255 255\n"
           "3 0 4 1\n3 1 4 2\n3 2 4 3\n3 3 4 0\n4 0 1 2 3\n";
}

}  // namespace test_support
