// loader-lab: which library should read glTF 2.0, STL, PLY and OBJ. On assimp's own test models it
// times the product's reader (raster::read_model), assimp alone, tinygltf (glTF only) and
// tinyobjloader (OBJ only), compares what each one read (triangles, vertices, bounding box,
// materials, textures), and feeds each of them assimp's malformed files in a child process, so
// that a crash or a hang is recorded rather than fatal.
// Writes loaders.csv and loaders-summary.md; lab/loader_chart.gp draws loaders.svg.
#include "lab_args.hpp"

#include "io/image_header.hpp"

#include <raster/geometry/mesh.hpp>
#include <raster/geometry/model.hpp>
#include <raster/io/model_file.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_obj_loader.h>
// Images reach our callback as bytes: stb is compiled once, in the product, not again here.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>

namespace {

namespace fs = std::filesystem;

// product-nomaps is the product without decoding texture maps: how much of its time the maps are;
// product-in-process reads in this process rather than a child: what the child process costs.
enum class Loader { product, product_nomaps, product_in_process, assimp, tinygltf, tinyobjloader };
constexpr std::array kLoaders{Loader::product, Loader::product_nomaps, Loader::product_in_process, Loader::assimp, Loader::tinygltf, Loader::tinyobjloader};

const char* name_of(Loader loader) {
    switch (loader) {
        case Loader::product: return "product";
        case Loader::product_nomaps: return "product-nomaps";
        case Loader::product_in_process: return "product-in-process";
        case Loader::assimp: return "assimp";
        case Loader::tinygltf: return "tinygltf";
        case Loader::tinyobjloader: return "tinyobjloader";
    }
    return "?";
}

// The deepest node hierarchy the walks follow, as the product's: RecursiveNodes loops for ever.
constexpr int kMaxNodeDepth = 256;
// A load that takes longer than this in its child process is recorded as a hang.
constexpr int kProbeSeconds = 20;
// Each timed sample loads the file enough times to last this long, so that small files are not
// timed at the clock's and the scheduler's resolution.
constexpr double kSampleSeconds = 0.02;
// Bounding boxes agree when no corner moves more than this fraction of the larger diagonal.
constexpr double kBoxTolerance = 1e-5;

struct Box {
    glm::dvec3 low{std::numeric_limits<double>::infinity()};
    glm::dvec3 high{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3& p) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
};

// What one loader made of one file, in the file's own (right-handed) coordinates.
struct Reading {
    std::size_t triangles = 0;
    std::size_t flat = 0;  // of which have no area (the product's facet_normal is zero): never drawn
    std::size_t vertices = 0;
    std::size_t materials = 0;  // that the triangles use: files and libraries differ on unused and default ones
    std::size_t textures = 0;   // diffuse or base-colour maps of those materials that were found
    Box box;
    std::string note;  // the loader's first warning, if it gave one

    // A triangle in the file's coordinates: counted, tested for area as the product tests it,
    // and its corners boxed (flat or not, as a renderer without the product's test would).
    void add_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        ++triangles;
        if (raster::facet_normal(glm::vec3(a), glm::vec3(b), glm::vec3(c)) == glm::vec3(0.0F)) ++flat;
        for (const glm::dvec3& p : {a, b, c}) box.add(p);
    }
    // What a renderer draws: the product drops triangles with no area (meshes_by_material).
    [[nodiscard]] std::size_t drawn() const noexcept { return triangles - flat; }
};

std::string one_line(std::string text, std::size_t limit = 160) {
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
    std::replace(text.begin(), text.end(), '|', '/');  // it would end a Markdown table's cell
    if (text.size() > limit) text = text.substr(0, limit - 3) + "...";
    return text;
}

// A CSV field: the file is read by gnuplot, which splits at every comma, quoted or not.
std::string field(std::string text, std::size_t limit = 400) {
    text = one_line(std::move(text), limit);
    std::replace(text.begin(), text.end(), ',', ';');
    return text;
}

std::string lower_extension(const fs::path& path) {
    std::string ending = path.extension().string();
    std::transform(ending.begin(), ending.end(), ending.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ending;
}

bool exists_quietly(const fs::path& path) {
    std::error_code error;
    return fs::is_regular_file(path, error);
}

// The library loaded the file, but what it handed over is not safe to use as it stands (an index
// past the vertices, a loop of nodes): found by our walk, which a program using it must make.
struct WalkError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ---- product ----------------------------------------------------------------------------------

// `apart`: in a child process under limits, as `render` reads; else in this one, to see what that costs.
Reading by_product(const fs::path& path, bool maps, bool apart = true) {
    raster::ObjOptions options;  // what `render` passes, maps included unless asked not to
    options.load_textures = maps;
    options.limits.separate_process = apart;
    const raster::Model model = raster::read_model(path, options);
    Reading r;
    r.triangles = raster::triangle_count(model);  // flat ones were dropped while building it
    std::set<const raster::Texture*> textures;
    for (const raster::ModelPart& part : model.parts) {
        r.vertices += part.mesh.positions.size();
        if (part.texture != nullptr) textures.insert(part.texture.get());
    }
    r.materials = model.parts.size();  // one part per material the triangles use
    r.textures = textures.size();
    const raster::Bounds bounds = raster::bounds_of(model);
    // raster mirrors z into its left-handed world; mirrored back to compare with the others.
    r.box.add({bounds.low.x, bounds.low.y, -bounds.high.z});
    r.box.add({bounds.high.x, bounds.high.y, -bounds.low.z});
    if (!model.warnings.empty()) r.note = model.warnings.front();
    return r;
}

// ---- assimp alone -----------------------------------------------------------------------------

glm::dmat4 matrix_of(const aiMatrix4x4& m) {
    glm::dmat4 out(1.0);
    for (unsigned row = 0; row < 4; ++row) {
        for (unsigned column = 0; column < 4; ++column) out[static_cast<int>(column)][static_cast<int>(row)] = m[row][column];
    }
    return out;
}

void walk_assimp(const aiScene& scene, const aiNode& node, const glm::dmat4& parent, int depth, Reading& r, std::set<unsigned>& used) {
    if (depth > kMaxNodeDepth) throw WalkError("nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep (or loop)");
    const glm::dmat4 world = parent * matrix_of(node.mTransformation);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes[i] >= scene.mNumMeshes) throw WalkError("a node names a mesh the scene lacks");
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        r.vertices += mesh.mNumVertices;  // per instance, as the product places every instance
        if (mesh.mNumFaces > 0) used.insert(mesh.mMaterialIndex);
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices < 3) continue;  // points and lines
            std::vector<glm::dvec3> corners;
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices) throw WalkError("a face names a vertex its mesh lacks");
                const aiVector3D& p = mesh.mVertices[face.mIndices[k]];
                corners.emplace_back(world * glm::dvec4(p.x, p.y, p.z, 1.0));
            }
            // A polygon (OBJ keeps them: no aiProcess_Triangulate) as its n - 2 fan triangles.
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) r.add_triangle(corners[0], corners[k], corners[k + 1]);
        }
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) {
        if (node.mChildren[i] != nullptr) walk_assimp(scene, *node.mChildren[i], world, depth + 1, r, used);
    }
}

Reading by_assimp(const fs::path& path) {
    Assimp::Importer importer;
    // The product's flags (src/io/scene_file.cpp): validation only, no triangulation or merging.
    const aiScene* scene = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
    if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) throw std::runtime_error(importer.GetErrorString());
    if (scene->mRootNode == nullptr) throw WalkError("no root node");
    Reading r;
    std::set<unsigned> used;
    walk_assimp(*scene, *scene->mRootNode, glm::dmat4(1.0), 0, r, used);
    r.materials = used.size();
    // A map counts as found when it is embedded or its file is there: assimp does not decode it.
    std::set<std::string> maps;
    for (const unsigned i : used) {
        if (i >= scene->mNumMaterials) continue;
        aiString map;
        const aiMaterial& m = *scene->mMaterials[i];
        if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &map) != AI_SUCCESS && m.GetTexture(aiTextureType_DIFFUSE, 0, &map) != AI_SUCCESS) continue;
        if (scene->GetEmbeddedTexture(map.C_Str()) != nullptr || exists_quietly(path.parent_path() / map.C_Str())) maps.insert(map.C_Str());
    }
    r.textures = maps.size();
    return r;
}

// ---- tinygltf ---------------------------------------------------------------------------------

// tinygltf's image callback: reads the size from the header, decodes nothing, refuses nothing.
bool note_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes, int size, void* found) {
    try {
        const raster::detail::ImageHeader header = raster::detail::read_image_header({bytes, static_cast<std::size_t>(std::max(size, 0))});
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
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) throw WalkError("an accessor the file lacks");
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) throw WalkError("a sparse accessor (not walked here)");
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) throw WalkError("an accessor without a buffer view");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size()) throw WalkError("a view of a buffer the file lacks");
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) throw WalkError("a buffer view past its buffer's end");
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
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != TINYGLTF_TYPE_VEC3) throw WalkError("POSITION is not float VEC3");
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
    if (a.type != TINYGLTF_TYPE_SCALAR || (bytes != 1 && bytes != 2 && bytes != 4) || a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
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
        if (out[i] >= vertices) throw WalkError("an index past the vertices (" + std::to_string(out[i]) + " of " + std::to_string(vertices) + ")");
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
    if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4) m *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

void walk_gltf(const tinygltf::Model& model, int index, const glm::dmat4& parent, int depth, Reading& r, std::set<int>& used) {
    if (depth > kMaxNodeDepth) throw WalkError("nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep (or loop)");
    if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size()) throw WalkError("a node the file lacks");
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
    const glm::dmat4 world = parent * local_matrix(node);
    if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= model.meshes.size()) throw WalkError("a node names a mesh the file lacks");
        for (const tinygltf::Primitive& primitive : model.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
            const bool list = primitive.mode == -1 || primitive.mode == TINYGLTF_MODE_TRIANGLES;
            const bool strip = primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP, fan = primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN;
            if (!list && !strip && !fan) continue;  // points and lines
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) throw WalkError("a primitive without POSITION");
            const std::vector<glm::dvec3> points = positions_of(model, position->second);
            const std::vector<std::uint32_t> corners = indices_of(model, primitive.indices, points.size());
            r.vertices += points.size();
            if (corners.size() >= 3) used.insert(primitive.material);
            const auto placed = [&](std::size_t k) { return glm::dvec3(world * glm::dvec4(points[corners[k]], 1.0)); };
            if (list) {
                for (std::size_t k = 0; k + 2 < corners.size(); k += 3) r.add_triangle(placed(k), placed(k + 1), placed(k + 2));
            } else {
                for (std::size_t k = 0; k + 2 < corners.size(); ++k) r.add_triangle(strip ? placed(k) : placed(0), placed(k + 1), placed(k + 2));
            }
        }
    }
    for (const int child : node.children) walk_gltf(model, child, world, depth + 1, r, used);
}

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
        const std::size_t scene = model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) < model.scenes.size()
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
        if (image >= 0 && static_cast<std::size_t>(image) < model.images.size() && model.images[static_cast<std::size_t>(image)].width > 0) maps.insert(image);
    }
    r.textures = maps.size();
    r.note = warning;
    return r;
}

// ---- tinyobjloader ----------------------------------------------------------------------------

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
                if (v < 0 || static_cast<std::size_t>(v) >= r.vertices) throw WalkError("a face names a vertex the file lacks");
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

// ---- running them -----------------------------------------------------------------------------

Reading read_with(Loader loader, const fs::path& path) {
    switch (loader) {
        case Loader::product: return by_product(path, true);
        case Loader::product_nomaps: return by_product(path, false);
        case Loader::product_in_process: return by_product(path, true, false);
        case Loader::assimp: return by_assimp(path);
        case Loader::tinygltf: return by_tinygltf(path);
        case Loader::tinyobjloader: return by_tinyobjloader(path);
    }
    throw std::logic_error("no such loader");
}

// Which loaders a file is for: each library only reads its own formats; assimp and the product all.
bool reads(Loader loader, const fs::path& path) {
    const std::string ending = lower_extension(path);
    if (loader == Loader::tinygltf) return ending == ".gltf" || ending == ".glb";
    if (loader == Loader::tinyobjloader) return ending == ".obj";
    return true;
}

// How a load in a child process ended: "accepted", "refused", "loaded, unsafe" (the library took it
// but our walk found it unusable), "crashed (...)", "hung (...)" or "died (...)".
struct Outcome {
    std::string status;
    Reading reading;
    std::string message;  // why it refused, or its first warning
};

std::string encode(const Reading& r) {
    std::ostringstream out;
    out.precision(17);
    out << r.triangles << ' ' << r.flat << ' ' << r.vertices << ' ' << r.materials << ' ' << r.textures;
    for (const glm::dvec3& p : {r.box.low, r.box.high}) out << ' ' << p.x << ' ' << p.y << ' ' << p.z;
    out << ' ' << one_line(r.note, 400);
    return out.str();
}

Reading decode(const std::string& text) {
    // strtod, not operator>>: the box of a file with infinite vertices is written as inf.
    Reading r;
    const char* at = text.c_str();
    char* end = nullptr;
    const auto next = [&] {
        const double v = std::strtod(at, &end);
        at = end;
        return v;
    };
    r.triangles = static_cast<std::size_t>(next());
    r.flat = static_cast<std::size_t>(next());
    r.vertices = static_cast<std::size_t>(next());
    r.materials = static_cast<std::size_t>(next());
    r.textures = static_cast<std::size_t>(next());
    r.box.low = {next(), next(), next()};
    r.box.high = {next(), next(), next()};
    while (*at == ' ') ++at;
    r.note = at;
    return r;
}

void write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

// Loads the file once in a forked child: a loader that crashes or loops takes only the child down.
Outcome probe(Loader loader, const fs::path& path) {
    std::array<int, 2> channel{};
    if (pipe(channel.data()) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
    std::cout.flush();
    std::cerr.flush();
    const pid_t child = fork();
    if (child < 0) throw std::system_error(errno, std::generic_category(), "fork");
    if (child == 0) {
        close(channel[0]);
        std::string line;
        try {
            line = "accepted " + encode(read_with(loader, path));
        } catch (const WalkError& problem) {
            line = "unsafe " + one_line(problem.what(), 400);
        } catch (const std::exception& problem) {
            line = "refused " + one_line(problem.what(), 400);
        }
        write_all(channel[1], line);
        _exit(0);  // no destructors or stdio flushes of the parent's state
    }
    close(channel[1]);
    std::string text;
    bool hung = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kProbeSeconds);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            hung = true;
            break;
        }
        pollfd ready{channel[0], POLLIN, 0};
        const int events = poll(&ready, 1, static_cast<int>(left));
        if (events <= 0) continue;  // interrupted or timed out: the deadline decides
        std::array<char, 4096> buffer{};
        const ssize_t got = read(channel[0], buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;  // the child finished, or died
        text.append(buffer.data(), static_cast<std::size_t>(got));
    }
    close(channel[0]);
    if (hung) kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    Outcome outcome;
    if (hung) {
        outcome.status = "hung (killed after " + std::to_string(kProbeSeconds) + " s)";
    } else if (WIFSIGNALED(status)) {
        const char* signal_name = sigabbrev_np(WTERMSIG(status));
        outcome.status = std::string("crashed (SIG") + (signal_name != nullptr ? signal_name : std::to_string(WTERMSIG(status)).c_str()) + ")";
    } else if (text.rfind("accepted ", 0) == 0) {
        outcome.status = "accepted";
        outcome.reading = decode(text.substr(9));
        outcome.message = outcome.reading.note;
    } else if (text.rfind("refused ", 0) == 0) {
        outcome.status = "refused";
        outcome.message = text.substr(8);
    } else if (text.rfind("unsafe ", 0) == 0) {
        outcome.status = "loaded, unsafe";
        outcome.message = "our walk: " + text.substr(7);
    } else {
        outcome.status = "died (exit " + std::to_string(WEXITSTATUS(status)) + ")";
    }
    return outcome;
}

// Why two readings differ, or "" when they draw as many triangles in the same bounding box.
std::string difference(const Reading& a, const Reading& b) {
    if (a.drawn() != b.drawn()) return std::to_string(a.drawn()) + " triangles with area against " + std::to_string(b.drawn());
    const double diagonal = std::max(glm::length(a.box.high - a.box.low), glm::length(b.box.high - b.box.low));
    for (int k = 0; k < 3; ++k) {
        for (const auto& [x, y] : {std::pair{a.box.low[k], b.box.low[k]}, std::pair{a.box.high[k], b.box.high[k]}}) {
            if (x == y) continue;  // equal, infinities included
            if (!std::isfinite(diagonal) || !(std::abs(x - y) <= kBoxTolerance * diagonal)) {
                char text[120];
                std::snprintf(text, sizeof text, "box %c %.7g against %.7g", "xyz"[k], x, y);
                return text;
            }
        }
    }
    return "";
}

struct Case {
    std::string label;  // as the chart and tables name it
    fs::path path;
    bool malformed;
    std::map<Loader, Outcome> outcomes{};
    std::map<Loader, std::vector<double>> seconds{};  // one per round: the mean load of a batch
    std::map<Loader, int> batch{};
    std::map<Loader, std::string> disagreements{};
};

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
        broken.emplace_back(std::string("wrongTypes/") + name + ".gltf", std::string("glTF2/wrongTypes/") + name + ".gltf");
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
                broken.emplace_back(std::string(folder) + "/" + p.filename().string(), fs::relative(p, models).string());
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

// Milliseconds to three significant figures, without an exponent.
std::string ms(double seconds) {
    const double v = seconds * 1000.0;
    char text[32];
    std::snprintf(text, sizeof text, v >= 100 ? "%.0f" : v >= 10 ? "%.1f" : v >= 1 ? "%.2f" : "%.3f", v);
    return text;
}

std::string point(const glm::dvec3& p) {
    char text[100];
    std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
    return text;
}

double quantile(std::vector<double> values, double q) {
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

// One batch: the mean time of `count` loads, each one's triangles checked against the probe's.
double time_batch(Loader loader, const Case& c, int count) {
    const std::size_t expected = c.outcomes.at(loader).reading.triangles;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i) {
        if (read_with(loader, c.path).triangles != expected) throw std::runtime_error(c.label + ": " + name_of(loader) + " read it differently twice");
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / count;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path out = "doc/lab";
    fs::path models = "/usr/share/assimp/models";
    int rounds = 15;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--out=", 0) == 0) {
            out = arg.substr(6);
        } else if (arg.rfind("--models=", 0) == 0) {
            models = arg.substr(9);
        } else if (arg.rfind("--rounds=", 0) == 0) {
            rounds = std::max(1, std::atoi(arg.substr(9).c_str()));
        } else {
            std::cerr << "usage: loader-lab [--out=DIR] [--models=DIR (assimp-testmodels)] [--rounds=N]\n";
            return 2;
        }
    }
    fs::create_directories(out);
    std::vector<Case> all = cases(models);
    if (all.empty()) {
        std::cerr << "loader-lab: no test models under " << models.string() << " (apt-get install assimp-testmodels)\n";
        return 1;
    }
    // Every (file, loader) once in a child process first: what it read, refused, or died of.
    for (Case& c : all) {
        for (const Loader loader : kLoaders) {
            if (!reads(loader, c.path) || (c.malformed && (loader == Loader::product_nomaps || loader == Loader::product_in_process))) continue;
            c.outcomes[loader] = probe(loader, c.path);
            Outcome& o = c.outcomes[loader];
            // The product names the file first ("file: ..." or "file:12: ..."); the tables already do.
            if (const std::string named = c.path.string() + ":"; o.message.rfind(named, 0) == 0) {
                o.message.erase(0, named.size());
                const std::size_t digits = o.message.find_first_not_of("0123456789");
                if (digits > 0 && digits != std::string::npos && o.message[digits] == ':') o.message = "line " + o.message;
                if (o.message.rfind(' ', 0) == 0) o.message.erase(0, 1);
            }
            std::cerr << "loader-lab: " << c.label << ", " << name_of(loader) << ": " << o.status;
            if (o.status == "accepted") std::cerr << ", " << o.reading.triangles << " triangles";
            if (!o.message.empty()) std::cerr << " - " << o.message;
            std::cerr << '\n';
        }
        // Each accepted reading against every other accepted one of the same file.
        for (const auto& [loader, o] : c.outcomes) {
            if (o.status != "accepted") continue;
            std::string why;
            for (const auto& [other, p] : c.outcomes) {
                if (other == loader || p.status != "accepted") continue;
                const std::string d = difference(o.reading, p.reading);
                if (!d.empty()) why += (why.empty() ? "" : "; ") + std::string("vs ") + name_of(other) + ": " + d;
            }
            c.disagreements[loader] = why;
        }
    }
    // Timing, in this process, of well-formed files each loader accepted. A warm-up load sets the
    // batch; then round after round, every file by every loader, the loaders' order turning each
    // round so that none is always the first to touch a file.
    for (Case& c : all) {
        if (c.malformed) continue;
        for (const auto& [loader, o] : c.outcomes) {
            if (o.status != "accepted") continue;
            const double once = time_batch(loader, c, 1);
            c.batch[loader] = static_cast<int>(std::clamp(std::ceil(kSampleSeconds / std::max(once, 1e-9)), 1.0, 1000.0));
        }
    }
    for (int r = 0; r < rounds; ++r) {
        for (Case& c : all) {
            if (c.malformed || c.batch.empty()) continue;
            std::vector<Loader> order;
            for (const auto& [loader, count] : c.batch) order.push_back(loader);
            std::rotate(order.begin(), order.begin() + r % static_cast<int>(order.size()), order.end());
            for (const Loader loader : order) c.seconds[loader].push_back(time_batch(loader, c, c.batch[loader]));
        }
        std::cerr << "loader-lab: round " << r + 1 << " of " << rounds << " timed\n";
    }

    std::ofstream csv(out / "loaders.csv");
    csv << "kind,file_index,file,path,loader,status,samples,batch,median_ms,q1_ms,q3_ms,min_ms,max_ms,triangles,flat,vertices,materials,textures,"
           "low_x,low_y,low_z,high_x,high_y,high_z,agrees,message\n";
    int index = 0;
    for (const Case& c : all) {
        for (const auto& [loader, o] : c.outcomes) {
            csv << (c.malformed ? "malformed" : "wellformed") << ',' << index << ',' << field(c.label) << ','
                << field(fs::relative(c.path, models).string()) << ',' << name_of(loader) << ',' << field(o.status) << ',';
            const auto times = c.seconds.find(loader);
            if (times != c.seconds.end()) {
                const std::vector<double>& t = times->second;
                csv << t.size() << ',' << c.batch.at(loader) << ',' << lab::median(t) * 1e3 << ',' << quantile(t, 0.25) * 1e3 << ','
                    << quantile(t, 0.75) * 1e3 << ',' << *std::min_element(t.begin(), t.end()) * 1e3 << ','
                    << *std::max_element(t.begin(), t.end()) * 1e3 << ',';
            } else {
                csv << ",,,,,,,";
            }
            if (o.status == "accepted") {
                const Reading& g = o.reading;
                csv << g.triangles << ',' << g.flat << ',' << g.vertices << ',' << g.materials << ',' << g.textures << ',' << g.box.low.x << ',' << g.box.low.y << ','
                    << g.box.low.z << ',' << g.box.high.x << ',' << g.box.high.y << ',' << g.box.high.z << ','
                    << (c.disagreements.at(loader).empty() ? "yes" : "no") << ',';
            } else {
                csv << ",,,,,,,,,,,,";
            }
            const std::string& why = o.status == "accepted" && !c.disagreements.at(loader).empty() ? c.disagreements.at(loader) : o.message;
            csv << field(why) << '\n';
        }
        ++index;
    }

    std::ofstream summary(out / "loaders-summary.md");
    summary << "Load time, ms: median of " << rounds << " rounds (each the mean of a batch of loads lasting about " << kSampleSeconds * 1e3
            << " ms), with the fastest and slowest round. Files from assimp-testmodels (" << models.string() << ").\n\n";
    summary << "| file | triangles in the file | product | product-nomaps | product-in-process | assimp | tinygltf | tinyobjloader |\n|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : all) {
        if (c.malformed) continue;
        std::size_t triangles = 0;
        for (const auto& [loader, o] : c.outcomes) {
            if (o.status == "accepted") triangles = std::max(triangles, o.reading.triangles);
        }
        summary << "| " << c.label << " | " << triangles;
        for (const Loader loader : kLoaders) {
            const auto o = c.outcomes.find(loader);
            summary << " | ";
            if (o == c.outcomes.end()) {
                summary << "-";
            } else if (const auto t = c.seconds.find(loader); t != c.seconds.end()) {
                summary << ms(lab::median(t->second)) << " (" << ms(*std::min_element(t->second.begin(), t->second.end())) << "-"
                        << ms(*std::max_element(t->second.begin(), t->second.end())) << ")";
            } else {
                summary << o->second.status;
            }
        }
        summary << " |\n";
    }
    summary << "\nWhat each read (the file's own axes; assimp and tinygltf placed by the node matrices, as the product is). No area: "
               "triangles whose corners the product's facet_normal finds collinear or coincident (it drops them). Agrees: as many triangles "
               "with area, in a bounding box within "
            << kBoxTolerance << " of its diagonal, as every other loader that accepted the file.\n\n";
    summary << "| file | loader | triangles | no area | vertices | materials | textures | box min | box max | agrees |\n"
               "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Case& c : all) {
        if (c.malformed) continue;
        for (const auto& [loader, o] : c.outcomes) {
            summary << "| " << c.label << " | " << name_of(loader) << " | ";
            if (o.status != "accepted") {
                summary << o.status << (o.message.empty() ? "" : ": " + one_line(o.message, 100)) << " | | | | | | | |\n";
                continue;
            }
            const Reading& g = o.reading;
            const std::string& why = c.disagreements.at(loader);
            summary << g.triangles << " | " << g.flat << " | " << g.vertices << " | " << g.materials << " | " << g.textures << " | " << point(g.box.low) << " | "
                    << point(g.box.high) << " | " << (why.empty() ? "yes" : "no: " + why) << " |\n";
        }
    }
    summary << "\nMalformed files, each loader run once in a child process (killed after " << kProbeSeconds << " s).\n\n";
    summary << "| file | product | assimp | tinygltf | tinyobjloader |\n|---|---|---|---|---|\n";
    for (const Case& c : all) {
        if (!c.malformed) continue;
        summary << "| " << c.label;
        for (const Loader loader : {Loader::product, Loader::assimp, Loader::tinygltf, Loader::tinyobjloader}) {
            const auto o = c.outcomes.find(loader);
            summary << " | ";
            if (o == c.outcomes.end()) {
                summary << "-";
                continue;
            }
            summary << o->second.status;
            if (o->second.status == "accepted") summary << ", " << o->second.reading.triangles << " triangles";
            if (!o->second.message.empty()) summary << ": " << one_line(o->second.message, 90);
        }
        summary << " |\n";
    }
    std::cerr << "loader-lab: wrote loaders.csv and loaders-summary.md in " << out.string() << "\n";
    return 0;
}
