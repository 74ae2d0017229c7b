// One assimp scene as raster's Model: nodes walked, meshes placed, materials read; stays whole so the walk reads as
// one.
#include "io/assimp/scene_model.hpp"

#include "geometry/polygon_triangles.hpp"
#include "io/assimp/gltf_material.hpp"
#include "io/assimp/material_alpha.hpp"
#include "io/gltf/gltf_structure.hpp"
#include "io/model_builder.hpp"
#include "io/named_path.hpp"
#include "io/vertex_alpha.hpp"

#include <raster/image/colour.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/texture_file.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>
#include <assimp/material.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace raster::detail {
namespace {

glm::dmat4 matrix_of(const aiMatrix4x4& m) {
    // assimp's matrices are row-major with translation in the last column; GLM's are column-major.
    return glm::transpose(
        glm::dmat4(m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4));
}

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What linear_from_srgb_channel gives each byte b read as b / 255 in float, as assimp reads
// colour bytes: a cloud's millions of colours are looked up, not raised to a power each.
std::array<float, 256> linear_bytes() {
    std::array<float, 256> linear{};
    for (std::size_t b = 0; b < linear.size(); ++b)
        linear[b] = static_cast<float>(linear_from_srgb_channel(static_cast<float>(b) / 255.0F));
    return linear;
}

// A file's colour channel in linear light: clamped to [0, 1], white where it is not a number.
float linear_channel(float written, ColourSpace space, const std::array<float, 256>& bytes) {
    const float c = std::isfinite(written) ? std::clamp(written, 0.0F, 1.0F) : 1.0F;
    if (space != ColourSpace::srgb) return c;
    const auto b = static_cast<std::size_t>(c * 255.0F + 0.5F);
    if (static_cast<float>(b) / 255.0F == c) return bytes[b];  // the same input, so the same value
    return static_cast<float>(linear_from_srgb_channel(c));
}

class SceneReader {
public:
    SceneReader(const aiScene& scene, const std::filesystem::path& path, ColourSpace colours, const ObjOptions& options,
                Model& model)
        : scene_(scene), path_(path), name_(printable(path.string())), colours_(colours), options_(options),
          model_(model) {}

    PolygonSoup soup() {
        if (scene_.mRootNode == nullptr) throw std::runtime_error("it holds no scene");
        visit(*scene_.mRootNode, glm::dmat4(1.0), 0);
        if (unplaced_ > 0) {
            model_.warnings.push_back(name_ + ": skipped " + std::to_string(unplaced_) +
                                      " points or line ends that are not finite points");
        }
        warn_of_vertex_alphas(name_, unreadable_alphas_, model_.warnings);
        return std::move(soup_);
    }

    // Each material's Phong and diffuse map (and glTF's metallic-roughness); unreadable maps warn.
    struct Material {
        LinearMaterial phong;
        std::shared_ptr<const Texture> texture;
        std::optional<MetallicRoughness> pbr;
    };
    std::vector<Material> materials(const GltfFacts* gltf) {
        std::vector<Material> out;
        for (unsigned i = 0; i < scene_.mNumMaterials; ++i) {
            const aiMaterial& m = *scene_.mMaterials[i];
            Material& material =
                out.emplace_back(Material{phong_from(m), options_.load_textures ? map_of(m) : nullptr, {}});
            if (!is_gltf_material(m)) continue;
            // assimp 5.2 appends its default material, which no material of the file's names.
            const bool assimps_default = i + 1 == scene_.mNumMaterials;
            material.pbr = gltf_factors(m, name_, assimps_default || gltf == nullptr ? nullptr : gltf, model_.warnings);
            if (!options_.load_textures) continue;
            for (const GltfMap& map : kGltfMaps) (*material.pbr).*map.slot = map_of(m, map.type, map.encoding);
        }
        return out;
    }

private:
    void visit(const aiNode& node, const glm::dmat4& parent, int depth) {
        if (depth > kMaxGltfNodeDepth)
            throw std::runtime_error("its nodes nest more than " + std::to_string(kMaxGltfNodeDepth) +
                                     " deep (or loop)");
        if (!on_path_.insert(&node).second) throw std::runtime_error("its node hierarchy loops");
        const glm::dmat4 world = parent * matrix_of(node.mTransformation);
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes[i] >= scene_.mNumMeshes)
                throw std::runtime_error("a node names mesh " + std::to_string(node.mMeshes[i]) + ", which it lacks");
            add_mesh(*scene_.mMeshes[node.mMeshes[i]], world);
        }
        for (unsigned i = 0; i < node.mNumChildren; ++i) {
            if (node.mChildren[i] != nullptr) visit(*node.mChildren[i], world, depth + 1);
        }
        on_path_.erase(&node);
    }

    // Positions and normals moved by the node's matrix, then mirrored into raster's left-handed
    // world as OBJ's are; faces split into their own outline and re-wound to match.
    void add_mesh(const aiMesh& mesh, const glm::dmat4& world) {
        if (soup_.positions.size() + mesh.mNumVertices >= kMaxSoupVertices)
            throw std::runtime_error("more vertices than raster indexes in 32 bits");
        const auto first = static_cast<std::uint32_t>(soup_.positions.size());
        const bool has_normals = mesh.mNormals != nullptr, has_uvs = mesh.mTextureCoords[0] != nullptr;
        const bool has_colours = mesh.mColors[0] != nullptr;
        const bool has_tangents = mesh.mTangents != nullptr && has_normals && has_uvs;
        // Normals, texture coordinates, colours and tangents are kept one per position: meshes without them pad.
        if (has_normals) soup_.normals.resize(soup_.positions.size(), glm::vec3(0.0F));
        if (has_uvs) soup_.uvs.resize(soup_.positions.size(), glm::vec2(0.0F));
        if (has_colours) soup_.colours.resize(soup_.positions.size(), LinearRgb{1.0F, 1.0F, 1.0F});
        if (has_tangents) soup_.tangents.resize(soup_.positions.size(), glm::vec4(0.0F));
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        // Each mirror turns a tangent's handedness: the node's, if its matrix mirrors, and the z mirror into our world.
        const double handedness = glm::determinant(glm::dmat3(world)) < 0.0 ? 1.0 : -1.0;
        soup_.positions.reserve(soup_.positions.size() + mesh.mNumVertices);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            if (!finite(p)) {  // only a face refuses it: a scanner marks missing points so
                soup_.positions.emplace_back(std::numeric_limits<float>::quiet_NaN());
                if (has_normals) soup_.normals.emplace_back(0.0F);
                if (has_uvs) soup_.uvs.emplace_back(0.0F);
                if (has_colours) soup_.colours.push_back({1.0F, 1.0F, 1.0F});
                if (has_tangents) soup_.tangents.emplace_back(0.0F);
                continue;
            }
            const glm::dvec3 placed = glm::dvec3(world * glm::dvec4(p.x, p.y, p.z, 1.0));
            soup_.positions.emplace_back(placed.x, placed.y, -placed.z);
            if (mesh.mNormals != nullptr) {
                const aiVector3D& n = mesh.mNormals[v];
                const glm::dvec3 turned = finite(n) ? normal_matrix * glm::dvec3(n.x, n.y, n.z) : glm::dvec3(0.0);
                soup_.normals.emplace_back(turned.x, turned.y, -turned.z);
            }
            if (mesh.mTextureCoords[0] != nullptr) {
                const aiVector3D& uv = mesh.mTextureCoords[0][v];
                soup_.uvs.emplace_back(std::isfinite(uv.x) ? uv.x : 0.0F, std::isfinite(uv.y) ? uv.y : 0.0F);
            }
            if (has_colours) {
                const aiColor4D& c = mesh.mColors[0][v];
                soup_.colours.push_back({linear_channel(c.r, colours_, linear_bytes_),
                                         linear_channel(c.g, colours_, linear_bytes_),
                                         linear_channel(c.b, colours_, linear_bytes_)});
                const float alpha = vertex_alpha(c.a, unreadable_alphas_);
                if (alpha < 1.0F || !soup_.alphas.empty()) {  // kept from the first vertex that is see-through
                    soup_.alphas.resize(soup_.colours.size() - 1, 1.0F);
                    soup_.alphas.push_back(alpha);
                }
            }
            if (has_tangents) soup_.tangents.push_back(tangent_of(mesh, v, world, handedness));
        }
        const auto corner_at = [&](unsigned index) {
            if (index >= mesh.mNumVertices) {
                throw std::runtime_error("a face names vertex " + std::to_string(index) + " of a mesh of " +
                                         std::to_string(mesh.mNumVertices));
            }
            const std::uint32_t at = first + index;
            return SoupCorner{at, has_normals ? at : kNoIndex, has_uvs ? at : kNoIndex, has_colours ? at : kNoIndex,
                              has_tangents ? at : kNoIndex};
        };
        const auto drawable = [&](const SoupCorner& corner) {
            if (std::isfinite(soup_.positions[static_cast<std::size_t>(corner.position)].x)) return true;
            ++unplaced_;
            return false;
        };
        const int material = static_cast<int>(mesh.mMaterialIndex);
        if (mesh.mNumFaces == 0) {  // a point cloud, as assimp's PLY reader gives one
            soup_.points.reserve(soup_.points.size() + mesh.mNumVertices);
            for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
                if (const SoupCorner corner = corner_at(v); drawable(corner))
                    soup_.points.push_back({corner, material});
            }
        }
        std::vector<glm::dvec3> outline;
        std::vector<SoupCorner> corners;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices == 1) {
                if (const SoupCorner corner = corner_at(face.mIndices[0]); drawable(corner))
                    soup_.points.push_back({corner, material});
                continue;
            }
            if (face.mNumIndices == 2) {
                const SoupCorner a = corner_at(face.mIndices[0]), b = corner_at(face.mIndices[1]);
                if (drawable(a) && drawable(b)) soup_.segments.push_back({{a, b}, material});
                continue;
            }
            if (face.mNumIndices == 0) continue;  // validation refuses these
            if (face.mNumIndices > kMaxFaceCorners)
                throw std::runtime_error("a face of more than " + std::to_string(kMaxFaceCorners) + " corners");
            outline.clear();
            corners.clear();
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                corners.push_back(corner_at(face.mIndices[k]));
                outline.emplace_back(soup_.positions[static_cast<std::size_t>(corners.back().position)]);
                if (!std::isfinite(outline.back().x))
                    throw std::runtime_error("mesh '" + printable(mesh.mName.C_Str(), 80) +
                                             "' has a vertex that is not a finite point");
            }
            for (const auto& [a, b, c] : triangles_of_polygon(outline))
                soup_.triangles.push_back({{corners[a], corners[c], corners[b]}, material});
        }
        if (!soup_.normals.empty()) soup_.normals.resize(soup_.positions.size(), glm::vec3(0.0F));
        if (!soup_.uvs.empty()) soup_.uvs.resize(soup_.positions.size(), glm::vec2(0.0F));
        if (!soup_.colours.empty()) soup_.colours.resize(soup_.positions.size(), LinearRgb{1.0F, 1.0F, 1.0F});
        if (!soup_.tangents.empty()) soup_.tangents.resize(soup_.positions.size(), glm::vec4(0.0F));
    }

    // The file's tangent at vertex v moved by the node's matrix into raster's world; assimp gives glTF's w as
    // the bitangent w (n x t), read back from its sign. Zero (no tangent) where the file's is not finite.
    static glm::vec4 tangent_of(const aiMesh& mesh, unsigned v, const glm::dmat4& world, double handedness) {
        const aiVector3D& t = mesh.mTangents[v];
        if (!finite(t)) return glm::vec4(0.0F);
        double w = 1.0;
        if (mesh.mBitangents != nullptr && finite(mesh.mBitangents[v])) {
            const aiVector3D& n = mesh.mNormals[v];
            const aiVector3D& b = mesh.mBitangents[v];
            const glm::dvec3 across = glm::cross(glm::dvec3(n.x, n.y, n.z), glm::dvec3(t.x, t.y, t.z));
            if (glm::dot(across, glm::dvec3(b.x, b.y, b.z)) < 0.0) w = -1.0;
        }
        const glm::dvec3 moved = glm::dmat3(world) * glm::dvec3(t.x, t.y, t.z);
        const glm::vec3 unit = unit_or_zero(glm::vec3(glm::dvec3(moved.x, moved.y, -moved.z)));
        return glm::dot(unit, unit) > 0.0F ? glm::vec4(unit, static_cast<float>(w * handedness)) : glm::vec4(0.0F);
    }

    std::shared_ptr<const Texture> map_of(const aiMaterial& m) {
        aiString written;
        if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &written) != AI_SUCCESS &&
            m.GetTexture(aiTextureType_DIFFUSE, 0, &written) != AI_SUCCESS) {
            return nullptr;
        }
        return loaded(written, TexelEncoding::srgb);
    }
    // The material's map of `type`, its texels read as `encoding`; null when it has none.
    std::shared_ptr<const Texture> map_of(const aiMaterial& m, aiTextureType type, TexelEncoding encoding) {
        aiString written;
        if (m.GetTexture(type, 0, &written) != AI_SUCCESS) return nullptr;
        return loaded(written, encoding);
    }
    // Each file (or embedded image) read once for each encoding it is read in.
    std::shared_ptr<const Texture> loaded(const aiString& written, TexelEncoding encoding) {
        const std::string text = written.C_Str();
        const auto known = loaded_.find({text, encoding});
        if (known != loaded_.end()) return known->second;
        std::shared_ptr<const Texture> texture;
        try {
            if (const aiTexture* embedded = scene_.GetEmbeddedTexture(written.C_Str())) {
                if (embedded->mHeight != 0)
                    throw std::runtime_error("an embedded image of raw texels, which raster does not read");
                const auto* bytes = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
                texture =
                    std::make_shared<const Texture>(decode_texture({bytes, embedded->mWidth}, options_.max_texels));
            } else {
                const std::filesystem::path file = resolve_named_path(path_.parent_path(), text, options_.confine);
                if (FileIdentity identity; identity_of(file, identity))
                    model_.sources.push_back({file, identity, "texture"});
                texture = std::make_shared<const Texture>(
                    read_texture(file, options_.max_texels, options_.confine, &model_.sources));
            }
        } catch (const std::runtime_error& problem) {
            model_.warnings.push_back(name_ + ": texture '" + printable(text, 80) + "': " + problem.what() +
                                      "; drawing its material's colour");
        }
        if (texture && encoding != TexelEncoding::srgb)  // data, not colour: its mip chain averaged as data
            texture = std::make_shared<const Texture>(texture->level(0), encoding);
        loaded_.emplace(std::pair{text, encoding}, texture);
        return texture;
    }

    const aiScene& scene_;
    std::filesystem::path path_;
    std::string name_;
    ColourSpace colours_;
    std::array<float, 256> linear_bytes_ = linear_bytes();
    const ObjOptions& options_;
    Model& model_;
    PolygonSoup soup_;
    std::size_t unplaced_ = 0;           // points and line ends skipped for coordinates that are not finite
    std::size_t unreadable_alphas_ = 0;  // vertex alphas outside [0, 1] or not a number
    std::unordered_set<const aiNode*> on_path_;
    std::map<std::pair<std::string, TexelEncoding>, std::shared_ptr<const Texture>> loaded_;
};

}  // namespace

ColourSpace colour_space_of(std::string format) {
    std::transform(format.begin(), format.end(), format.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (format.starts_with(".")) format.erase(0, 1);
    return format == "gltf" || format == "glb" ? ColourSpace::linear : ColourSpace::srgb;
}

void model_from_scene(const aiScene& scene, const std::filesystem::path& path, const std::string& name,
                      ColourSpace colours, const ObjOptions& options, Model& model, const GltfFacts* gltf) {
    try {
        SceneReader reader(scene, path, colours, options, model);
        PolygonSoup soup = reader.soup();
        const auto materials = reader.materials(gltf);
        for (auto& [id, mesh] : meshes_by_material(soup, options.crease_degrees)) {
            ModelPart part{"", std::move(mesh), default_model_material()};
            if (id >= 0 && static_cast<std::size_t>(id) < materials.size()) {
                const aiString material_name = scene.mMaterials[id]->GetName();
                part.material_name = material_name.C_Str();
                const auto& material = materials[static_cast<std::size_t>(id)];
                part.material = material.phong;
                part.opacity = opacity_of(*scene.mMaterials[id],
                                          name + ": material '" + printable(part.material_name) + "'", model.warnings);
                if (!part.mesh.uvs.empty()) part.texture = material.texture;
                part.metallic_roughness = material.pbr;
                if (part.metallic_roughness && part.mesh.uvs.empty()) {  // maps need texture coordinates
                    for (const GltfMap& map : kGltfMaps) (*part.metallic_roughness).*map.slot = nullptr;
                }
            }
            settle_vertex_alphas(part, colours == ColourSpace::linear);  // glTF's COLOR_0 is the linear one
            // Tangents serve a normal map alone: a part without one does not carry them.
            if (!part.metallic_roughness || !part.metallic_roughness->normal_map) part.mesh.tangents = {};
            model.parts.push_back(std::move(part));
        }
    } catch (const std::runtime_error& problem) {
        throw std::runtime_error(name + ": " + problem.what());
    }
    if (model.parts.empty()) throw std::runtime_error(name + ": " + kNothingToDraw);
    const bool cameras = gltf != nullptr && !gltf->cameras.empty();
    if (cameras) model.cameras = gltf->cameras;
    for (const std::string& problem : gltf != nullptr ? gltf->camera_problems : std::vector<std::string>{})
        model.warnings.push_back(name + ": " + problem);
    warn_of_what_is_not_drawn(scene, name, model, cameras);
}

}  // namespace raster::detail
