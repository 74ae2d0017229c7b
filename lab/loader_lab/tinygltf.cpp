// tinygltf (glTF only), its images' sizes read by the product's header reader, its model walked
// with the bounds checks it leaves to its users.
#include "loader_lab/loaders.hpp"

#include "io/image_header.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
// Images reach our callback as bytes: stb is compiled once, in the product, not again here.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>

namespace loader_lab {
namespace {

// tinygltf's image callback: reads the size from the header, decodes nothing, refuses nothing.
bool note_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                int size, void* found) {
    try {
        const raster::detail::ImageHeader header =
            raster::detail::read_image_header({bytes, static_cast<std::size_t>(std::max(size, 0))});
        image->width = header.width;
        image->height = header.height;
        ++*static_cast<std::size_t*>(found);
    } catch (const std::runtime_error&) {
        // not an image raster reads: left uncounted, as the product would warn and draw the colour
    }
    return true;
}

// An accessor's elements of `element_bytes` each, checked to lie inside its view and buffer:
// tinygltf checks neither, so a reader of its model must.
struct Elements {
    const unsigned char* data;
    std::size_t stride;
    std::size_t count;
};

Elements elements_of(const tinygltf::Model& model, int index, std::size_t element_bytes) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        throw WalkError("an accessor the file lacks");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) throw WalkError("a sparse accessor (not walked here)");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
        throw WalkError("an accessor without a buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        throw WalkError("a view of a buffer the file lacks");
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
        throw WalkError("a buffer view past its buffer's end");
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : element_bytes;
    if (a.count > 0) {
        // Written so that nothing overflows: the last element must end inside the view.
        const bool fits = a.byteOffset <= view.byteLength && element_bytes <= view.byteLength - a.byteOffset &&
                          a.count - 1 <= (view.byteLength - a.byteOffset - element_bytes) / stride;
        if (!fits) throw WalkError("an accessor past its view's end");
    }
    return {buffer.data() + view.byteOffset + a.byteOffset, stride, a.count};
}

std::vector<glm::dvec3> positions_of(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != TINYGLTF_TYPE_VEC3)
        throw WalkError("POSITION is not float VEC3");
    const Elements e = elements_of(model, index, 3 * sizeof(float));
    std::vector<glm::dvec3> out(e.count);
    for (std::size_t i = 0; i < e.count; ++i) {
        std::array<float, 3> p{};
        std::memcpy(p.data(), e.data + i * e.stride, sizeof p);
        out[i] = glm::dvec3(p[0], p[1], p[2]);
    }
    return out;
}

std::vector<std::uint32_t> indices_of(const tinygltf::Model& model, int index, std::size_t vertices) {
    if (index < 0) {  // no indices: the vertices in order
        std::vector<std::uint32_t> all(vertices);
        for (std::size_t i = 0; i < vertices; ++i) all[i] = static_cast<std::uint32_t>(i);
        return all;
    }
    const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
    const int bytes = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (a.type != TINYGLTF_TYPE_SCALAR || (bytes != 1 && bytes != 2 && bytes != 4) ||
        a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        throw WalkError("indices that are not unsigned integers");
    }
    const Elements e = elements_of(model, index, static_cast<std::size_t>(bytes));
    std::vector<std::uint32_t> out(e.count);
    for (std::size_t i = 0; i < e.count; ++i) {
        const unsigned char* at = e.data + i * e.stride;
        if (bytes == 1) out[i] = *at;
        if (bytes == 2) {
            std::uint16_t v = 0;
            std::memcpy(&v, at, 2);
            out[i] = v;
        }
        if (bytes == 4) std::memcpy(&out[i], at, 4);
        if (out[i] >= vertices)
            throw WalkError("an index past the vertices (" + std::to_string(out[i]) + " of " +
                            std::to_string(vertices) + ")");
    }
    return out;
}

glm::dmat4 local_matrix(const tinygltf::Node& node) {
    glm::dmat4 m(1.0);
    if (node.matrix.size() == 16) {  // column-major in glTF, as in GLM
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<std::size_t>(c * 4 + r)];
        }
        return m;
    }
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

void walk_gltf(const tinygltf::Model& model, int index, const glm::dmat4& parent, int depth, Reading& r,
               std::set<int>& used) {
    if (depth > kMaxNodeDepth)
        throw WalkError("nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep (or loop)");
    if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size()) throw WalkError("a node the file lacks");
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * local_matrix(node);
    if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
            throw WalkError("a node names a mesh the file lacks");
        for (const tinygltf::Primitive& primitive : model.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            const bool list = primitive.mode == -1 || primitive.mode == TINYGLTF_MODE_TRIANGLES;
            const bool strip = primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP,
                       fan = primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN;
            if (!list && !strip && !fan) continue;  // points and lines
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) throw WalkError("a primitive without POSITION");
            const std::vector<glm::dvec3> points = positions_of(model, position->second);
            const std::vector<std::uint32_t> corners = indices_of(model, primitive.indices, points.size());
            r.vertices += points.size();
            if (corners.size() >= 3) used.insert(primitive.material);
            const auto placed = [&](std::size_t k) { return glm::dvec3(world * glm::dvec4(points[corners[k]], 1.0)); };
            if (list) {
                for (std::size_t k = 0; k + 2 < corners.size(); k += 3)
                    r.add_triangle(placed(k), placed(k + 1), placed(k + 2));
            } else {
                for (std::size_t k = 0; k + 2 < corners.size(); ++k)
                    r.add_triangle(strip ? placed(k) : placed(0), placed(k + 1), placed(k + 2));
            }
        }
    }
    for (const int child : node.children) walk_gltf(model, child, world, depth + 1, r, used);
}

}  // namespace

Reading by_tinygltf(const fs::path& path) {
    tinygltf::TinyGLTF loader;
    std::size_t images = 0;  // how many headers note_image read; the walk counts the ones used
    loader.SetImageLoader(&note_image, &images);
    tinygltf::Model model;
    std::string error, warning;
    const bool binary = lower_extension(path) == ".glb";
    const bool loaded = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                               : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
    if (!loaded) throw std::runtime_error(error.empty() ? "refused without a reason" : error);
    Reading r;
    std::set<int> used;  // -1 for glTF's default material
    // The default scene, else the first; the indices it reads are checked by the walk.
    if (!model.scenes.empty()) {
        const std::size_t scene =
            model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()
                ? static_cast<std::size_t>(model.defaultScene)
                : 0;
        for (const int root : model.scenes[scene].nodes) walk_gltf(model, root, glm::dmat4(1.0), 0, r, used);
    }
    r.materials = used.size();
    // A base-colour map is found when its image's header was read (note_image set its size).
    std::set<int> maps;
    for (const int m : used) {
        if (m < 0 || static_cast<std::size_t>(m) >= model.materials.size()) continue;
        const int texture = model.materials[static_cast<std::size_t>(m)].pbrMetallicRoughness.baseColorTexture.index;
        if (texture < 0 || static_cast<std::size_t>(texture) >= model.textures.size()) continue;
        const int image = model.textures[static_cast<std::size_t>(texture)].source;
        if (image >= 0 && static_cast<std::size_t>(image) < model.images.size() &&
            model.images[static_cast<std::size_t>(image)].width > 0)
            maps.insert(image);
    }
    r.textures = maps.size();
    r.note = warning;
    return r;
}

}  // namespace loader_lab
