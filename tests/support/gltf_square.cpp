#include "gltf_square.hpp"

#include "model_files.hpp"
#include "scratch.hpp"

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace test_support {

std::filesystem::path write_gltf_square(const std::filesystem::path& dir, const std::string& material,
                                        const std::string& extras, const std::string& nodes, bool strip_texture,
                                        const std::vector<float>& rgba) {
    std::string buffer;
    const auto put = [&](auto v) { buffer.append(reinterpret_cast<const char*>(&v), sizeof v); };
    for (const float v : {-1.0F, -1.0F, 0.0F, 1.0F, -1.0F, 0.0F, 1.0F, 1.0F, 0.0F, -1.0F, 1.0F, 0.0F}) put(v);
    for (const float v : {0.0F, 1.0F, 1.0F, 1.0F, 1.0F, 0.0F, 0.0F, 0.0F}) put(v);
    for (const int i : {0, 1, 2, 0, 2, 3}) put(static_cast<std::uint16_t>(i));
    for (const float v : rgba) put(v);  // at byte 92, a multiple of four
    std::ofstream(dir / "square.bin", std::ios::binary) << buffer;
    std::string textures;
    if (strip_texture) {
        raster::Framebuffer strip(4, 1);
        for (int x = 0; x < 4; ++x) strip.set_pixel(x, 0, x < 2 ? raster::Rgb{255, 0, 0} : raster::Rgb{0, 0, 255});
        write_png(dir / "strip.png", strip);
        textures = R"("images": [{"uri": "strip.png"}], "textures": [{"source": 0}],)";
    }
    const bool coloured = !rgba.empty();
    const std::string colour = coloured ? R"(, "COLOR_0": 3)" : "";
    const std::string colour_accessor =
        coloured ? R"(, {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC4"})" : "";
    const std::string colour_view =
        coloured ? R"(, {"buffer": 0, "byteOffset": 92, "byteLength": )" + std::to_string(rgba.size() * 4) + "}" : "";
    const std::string uses = material.empty() ? "" : R"(, "material": 0)";
    const std::string materials = material.empty() ? "" : R"("materials": [)" + material + "],";
    write_text(dir / "square.gltf", R"({"asset": {"version": "2.0"}, "scene": 0,)" + extras + R"(
  "scenes": [{"nodes": [0]}], "nodes": )" +
                                        nodes + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1)" +
                                        colour + R"(}, "indices": 2)" + uses + R"(}]}],
  )" + materials + textures + R"(
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"})" +
                                        colour_accessor + R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                  {"buffer": 0, "byteOffset": 80, "byteLength": 12})" +
                                        colour_view + R"(],
  "buffers": [{"byteLength": )" + std::to_string(buffer.size()) +
                                        R"(, "uri": "square.bin"}]})");
    return dir / "square.gltf";
}

}  // namespace test_support
