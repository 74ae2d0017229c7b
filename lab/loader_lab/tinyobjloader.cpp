// tinyobjloader (OBJ only), with its own triangulation, as a program using it alone would call it.
#include "loader_lab/loaders.hpp"

#include <set>
#include <string>
#include <vector>
#include <tiny_obj_loader.h>

namespace loader_lab {

Reading by_tinyobjloader(const fs::path& path) {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    const std::string directory = path.parent_path().string() + "/";
    // Its own triangulation on (the default), as a program using it alone would call it.
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, path.c_str(), directory.c_str())) {
        throw std::runtime_error(error.empty() ? "refused without a reason" : error);
    }
    Reading r;
    r.vertices = attrib.vertices.size() / 3;
    std::set<int> used;  // -1 for faces without a material
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const std::size_t count = shape.mesh.num_face_vertices[f];
            const std::size_t first = next;
            next += count;
            if (next > shape.mesh.indices.size()) throw WalkError("a face cut short");
            if (count < 3) continue;
            used.insert(f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1);
            std::vector<glm::dvec3> corners;
            for (std::size_t k = first; k < next; ++k) {
                const int v = shape.mesh.indices[k].vertex_index;
                if (v < 0 || static_cast<std::size_t>(v) >= r.vertices)
                    throw WalkError("a face names a vertex the file lacks");
                const std::size_t at = static_cast<std::size_t>(v) * 3;
                corners.emplace_back(attrib.vertices[at], attrib.vertices[at + 1], attrib.vertices[at + 2]);
            }
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) r.add_triangle(corners[0], corners[k], corners[k + 1]);
        }
    }
    r.materials = used.size();
    // Found when the name, as written, is a file beside the model: tinyobjloader reads no maps.
    std::set<std::string> maps;
    for (const int m : used) {
        if (m < 0 || static_cast<std::size_t>(m) >= materials.size()) continue;
        const std::string& map = materials[static_cast<std::size_t>(m)].diffuse_texname;
        if (!map.empty() && exists_quietly(path.parent_path() / map)) maps.insert(map);
    }
    r.textures = maps.size();
    r.note = warning;
    return r;
}

}  // namespace loader_lab
