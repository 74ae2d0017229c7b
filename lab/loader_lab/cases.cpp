#include "loader_lab/cases.hpp"

#include <algorithm>
#include <iostream>
#include <system_error>
#include <utility>

namespace loader_lab {

std::vector<Case> cases(const fs::path& models) {
    const std::vector<std::pair<std::string, std::string>> wellformed = {
        {"BoxTextured.glb", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"},
        {"BoxTextured.gltf + .bin + .png", "glTF2/BoxTextured-glTF/BoxTextured.gltf"},
        {"BoxTextured.gltf (embedded)", "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"},
        {"2CylinderEngine.glb", "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"},
        {"Spider_ascii.stl", "STL/Spider_ascii.stl"},
        {"Spider_binary.stl", "STL/Spider_binary.stl"},
        {"Wuson.stl", "STL/Wuson.stl"},
        {"Wuson.ply", "PLY/Wuson.ply"},
        {"cube_binary.ply", "PLY/cube_binary.ply"},
        {"float-color.ply", "PLY/float-color.ply"},
        {"spider.obj", "OBJ/spider.obj"},
        {"box.obj", "OBJ/box.obj"},
        {"WusonOBJ.obj", "OBJ/WusonOBJ.obj"},
    };
    std::vector<std::pair<std::string, std::string>> broken = {
        {"IndexOutOfRange.gltf", "glTF2/IndexOutOfRange/IndexOutOfRange.gltf"},
        {"AllIndicesOutOfRange.gltf", "glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf"},
        {"MissingBin/BoxTextured.gltf", "glTF2/MissingBin/BoxTextured.gltf"},
        {"BoxWithInfinites.glb", "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"},
        {"RecursiveNodes.gltf", "glTF2/RecursiveNodes/RecursiveNodes.gltf"},
    };
    for (const char* name : {"badArray", "badExtension", "badNumber", "badObject", "badString", "badUint"}) {
        broken.emplace_back(std::string("wrongTypes/") + name + ".gltf",
                            std::string("glTF2/wrongTypes/") + name + ".gltf");
    }
    // The folders of invalid files (glTF2/invalid in later releases): every one of a format we read.
    for (const char* folder : {"invalid", "glTF2/invalid"}) {
        std::error_code error;
        std::vector<fs::path> invalid;
        for (const auto& entry : fs::directory_iterator(models / folder, error)) invalid.push_back(entry.path());
        std::sort(invalid.begin(), invalid.end());
        for (const fs::path& p : invalid) {
            const std::string ending = lower_extension(p);
            if (ending == ".gltf" || ending == ".glb" || ending == ".stl" || ending == ".ply" || ending == ".obj") {
                broken.emplace_back(std::string(folder) + "/" + p.filename().string(),
                                    fs::relative(p, models).string());
            }
        }
    }
    std::vector<Case> all;
    for (const auto& [list, malformed] : {std::pair{&wellformed, false}, std::pair{&std::as_const(broken), true}}) {
        for (const auto& [label, relative] : *list) {
            if (exists_quietly(models / relative)) {
                all.push_back({label, models / relative, malformed});
            } else {
                std::cerr << "loader-lab: skipping " << (models / relative).string() << ", which is missing\n";
            }
        }
    }
    return all;
}

}  // namespace loader_lab
