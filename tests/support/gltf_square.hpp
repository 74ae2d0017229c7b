#pragma once

#include <filesystem>
#include <string>
#include <vector>

// A glTF square the material, extension and camera tests share, written beside its buffer.
namespace test_support {

// square.gltf and square.bin in `dir`: a square of side 2 in the file's z = 0 plane, facing +z,
// u running with x, drawn by `nodes` (node 0 holds the mesh) with `material` (JSON, or empty for
// a primitive without one); `extras` are more top-level fields ending in a comma. With
// `strip_texture`, texture 0 is strip.png, 4 x 1: red, red, blue, blue. `rgba`, when not empty,
// is a float VEC4 COLOR_0 for the corners (-1, -1), (1, -1), (1, 1), (-1, 1), four numbers each.
std::filesystem::path write_gltf_square(const std::filesystem::path& dir, const std::string& material,
                                        const std::string& extras = "", const std::string& nodes = R"([{"mesh": 0}])",
                                        bool strip_texture = false, const std::vector<float>& rgba = {});

}  // namespace test_support
