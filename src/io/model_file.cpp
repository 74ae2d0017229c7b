#include <raster/io/model_file.hpp>

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace raster {

Model read_model(const std::filesystem::path& path, const ObjOptions& options) {
    std::string ending = path.extension().string();
    std::transform(ending.begin(), ending.end(), ending.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ending == ".obj") return read_obj(path, options);
    if (ending == ".gltf" || ending == ".glb" || ending == ".stl" || ending == ".ply") return read_scene_file(path, options);
    throw std::runtime_error(printable(path.string()) + ": raster reads models ending in .obj, .gltf, .glb, .stl or .ply");
}

}  // namespace raster
