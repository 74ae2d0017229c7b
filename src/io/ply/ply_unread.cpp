#include "io/ply/ply_unread.hpp"

#include "io/ply/vertex_slots.hpp"

#include <raster/io/input_file.hpp>

#include <cstddef>

namespace raster::detail {
namespace {

// "vertex properties quality, intensity are not drawn", or the one "vertex property quality is".
std::string named(const std::string& name, const std::string& one, const std::string& many,
                  const std::vector<std::string>& names) {
    std::string text = name + ": " + (names.size() == 1 ? one : many) + " ";
    for (std::size_t k = 0; k < names.size(); ++k) text += (k > 0 ? ", " : "") + names[k];
    return text + (names.size() == 1 ? " is not drawn" : " are not drawn");
}

bool assimp_reads_element(const std::string& element) {
    return element == "material" || element == "tristrips" || element == "TextureFile";
}

}  // namespace

std::vector<std::string> ply_unread_warnings(const PlyLayout& layout, const std::string& name, bool for_assimp) {
    std::vector<std::string> vertex, face, elements;
    for (const PlyElement& element : layout.elements) {
        if (element.count == 0 || element.properties.empty()) continue;  // nothing of it is left out
        if (element.name == "vertex") {
            for (const PlyProperty& p : element.properties) {
                if (p.list || !VertexSlots::reads(p.name)) vertex.push_back(printable(p.name, 40));
            }
        } else if (element.name == "face") {
            const int corners = ply_corner_list(element);
            for (std::size_t k = 0; k < element.properties.size(); ++k) {
                const std::string& p = element.properties[k].name;
                const bool assimps = for_assimp && (p == "texcoord" || p == "material_index");
                if (static_cast<int>(k) != corners && !assimps) face.push_back(printable(p, 40));
            }
        } else if (!(for_assimp && assimp_reads_element(element.name))) {
            elements.push_back(printable(element.name, 40));
        }
    }
    std::vector<std::string> warnings;
    if (!vertex.empty()) warnings.push_back(named(name, "vertex property", "vertex properties", vertex));
    if (!face.empty()) warnings.push_back(named(name, "face property", "face properties", face));
    if (!elements.empty()) warnings.push_back(named(name, "element", "elements", elements));
    return warnings;
}

}  // namespace raster::detail
