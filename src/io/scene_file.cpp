// The only file that includes the Open Asset Import Library (glTF 2.0, STL, PLY).
#include <raster/io/model_file.hpp>

#include "io/model_builder.hpp"
#include "io/named_path.hpp"
#include "io/gltf_structure.hpp"
#include "io/ply_header.hpp"
#include "geometry/polygon_triangles.hpp"

#include <raster/image/colour.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/texture_file.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <string_view>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>
#include <assimp/BaseImporter.h>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace raster {

namespace {

// The checks a model file passes before assimp parses it, on every open: assimp opens some
// files twice, and a check made only the first time is no check.
std::string structure_problem(std::span<const std::uint8_t> bytes, const std::string& extension, const std::filesystem::path& directory,
                              const ObjOptions& options) {
    if (extension == ".ply") {
        if (std::string problem = detail::ply_header_problem(bytes); !problem.empty()) return problem;
        return detail::ply_counts_problem(bytes);
    }
    if (extension != ".gltf" && extension != ".glb") return "";
    return detail::gltf_structure_problem(bytes, extension == ".glb", [&](std::string_view uri) -> std::optional<std::uint64_t> {
        try {
            std::error_code error;
            const std::filesystem::path file = detail::resolve_named_path(directory, std::string(uri), options.confine);
            // Outside the confinement a size would tell an uploader something: its reader refuses it instead.
            if (!options.confine.empty() && std::filesystem::weakly_canonical(file, error).lexically_relative(options.confine).string().starts_with("..")) return std::nullopt;
            const std::uintmax_t size = std::filesystem::file_size(file, error);
            return error ? std::nullopt : std::optional<std::uint64_t>(size);
        } catch (const std::runtime_error&) {
            return std::nullopt;
        }
    });
}

// A stream over bytes in memory that leaves `open` when deleted, whoever deletes it.
class TrackedStream final : public Assimp::MemoryIOStream {
public:
    TrackedStream(const std::uint8_t* data, std::size_t size, std::unordered_set<TrackedStream*>& open)
        : Assimp::MemoryIOStream(data, size, false), open_(open) {}
    ~TrackedStream() override { open_.erase(this); }
    TrackedStream(const TrackedStream&) = delete;
    TrackedStream& operator=(const TrackedStream&) = delete;

private:
    std::unordered_set<TrackedStream*>& open_;
};

// Every file assimp opens (the model, glTF buffers and images) goes through InputFile: regular
// files only, sizes capped, confinement kept, each one remembered as an input of the run.
class BoundedFiles final : public Assimp::IOSystem {
public:
    // `model`: the file whose structure is checked whenever it is opened; `extension` its format.
    BoundedFiles(const ObjOptions& options, std::vector<InputRecord>& sources, std::filesystem::path model = {}, std::string extension = {})
        : options_(options), sources_(sources), model_(std::move(model)), extension_(std::move(extension)) {
        has_model_ = !model_.empty() && identity_of(model_, model_identity_);
    }
    ~BoundedFiles() override {
        // assimp deletes most streams itself, but not one it was reading when it threw.
        for (TrackedStream* stream : std::unordered_set<TrackedStream*>(open_)) delete stream;
    }
    BoundedFiles(const BoundedFiles&) = delete;
    BoundedFiles& operator=(const BoundedFiles&) = delete;

    bool Exists(const char* file) const override {
        FileIdentity identity;
        return identity_of(file, identity);
    }
    char getOsSeparator() const override { return '/'; }

    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;  // reading only
        InputRules rules;
        FileIdentity identity;
        const bool exists = identity_of(file, identity);
        const bool is_model = has_model_ && exists && identity == model_identity_;
        rules.role = is_model || sources_.empty() ? "model" : "model buffer";
        rules.max_bytes = kMaxModelFileBytes;
        rules.confine = options_.confine;
        try {
            if (exists && !is_model) sources_.push_back({file, identity, rules.role});
            if (is_model && !model_recorded_) {
                sources_.push_back({file, identity, rules.role});
                model_recorded_ = true;
            }
            auto bytes = std::make_unique<std::vector<std::uint8_t>>(read_input_file(file, rules));
            if (is_model) {
                if (std::string problem = structure_problem(*bytes, extension_, model_.parent_path(), options_); !problem.empty()) {
                    throw std::runtime_error(problem);
                }
            }
            // An empty file still gets a real address: assimp copies from it.
            const std::uint8_t* data = bytes->empty() ? &kNoByte : bytes->data();
            const std::size_t size = bytes->size();
            buffers_.push_back(std::move(bytes));
            auto* stream = new TrackedStream(data, size, open_);
            open_.insert(stream);
            return stream;
        } catch (const std::runtime_error& problem) {
            if (first_failure_.empty()) {
                first_failure_ = "'" + printable(file) + "' " + problem.what();
                first_reason_ = problem.what();
            }
            return nullptr;
        }
    }
    void Close(Assimp::IOStream* stream) override { delete stream; }

    // Why the first file that could not be opened was refused, or "".
    [[nodiscard]] const std::string& first_failure() const noexcept { return first_failure_; }
    // The same without the file's name: "does not exist".
    [[nodiscard]] const std::string& first_reason() const noexcept { return first_reason_; }

private:
    static constexpr std::uint8_t kNoByte = 0;
    const ObjOptions& options_;
    std::vector<InputRecord>& sources_;
    std::filesystem::path model_;
    std::string extension_;
    FileIdentity model_identity_;
    bool has_model_ = false;
    bool model_recorded_ = false;
    std::vector<std::unique_ptr<std::vector<std::uint8_t>>> buffers_;
    std::unordered_set<TrackedStream*> open_;
    std::string first_failure_;
    std::string first_reason_;
};

// Leaves `importer` only the reader of one format: when it declines a file, assimp would
// otherwise offer it to every reader it has (3DS, FBX, Collada, ...). Returns those taken out,
// which the caller now owns.
std::vector<std::unique_ptr<Assimp::BaseImporter>> keep_only_reader(Assimp::Importer& importer, const std::string& extension) {
    const std::string wanted = extension == ".glb" ? "glb" : extension.substr(1);
    std::vector<Assimp::BaseImporter*> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        const aiImporterDesc* about = importer.GetImporterInfo(i);
        const std::string name = about != nullptr && about->mName != nullptr ? about->mName : "";
        const std::string endings = about != nullptr && about->mFileExtensions != nullptr ? " " + std::string(about->mFileExtensions) + " " : "";
        const bool gltf2 = name.find("glTF2") != std::string::npos;
        const bool keep = endings.find(" " + wanted + " ") != std::string::npos && (wanted.starts_with("gl") ? gltf2 : true);
        if (!keep) others.push_back(importer.GetImporter(i));
    }
    std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;
    for (Assimp::BaseImporter* other : others) {
        if (importer.UnregisterLoader(other) == AI_SUCCESS) removed.emplace_back(other);
    }
    return removed;
}

glm::dmat4 matrix_of(const aiMatrix4x4& m) {
    // assimp's matrices are row-major with translation in the last column; GLM's are column-major.
    return glm::transpose(glm::dmat4(m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4));
}

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A glTF metallic-roughness material as raster's Phong (doc/conventions.md#models): the base
// colour is diffuse as far as the surface is not metal; the highlight is 4 % white for a
// dielectric and the base colour for a metal, as sharp as the roughness allows.
LinearMaterial material_from(const aiMaterial& m) {
    aiColor4D base(0.8F, 0.8F, 0.8F, 1.0F);
    if (m.Get(AI_MATKEY_BASE_COLOR, base) != AI_SUCCESS) m.Get(AI_MATKEY_COLOR_DIFFUSE, base);
    float metallic = 0.0F, roughness = 1.0F;
    const bool pbr = m.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
    if (pbr) m.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness);
    const auto usable = [](float v, float fallback) { return std::isfinite(v) ? std::clamp(v, 0.0F, 1.0F) : fallback; };
    metallic = usable(metallic, 0.0F);
    roughness = usable(roughness, 1.0F);
    const LinearRgb colour{std::max(0.0F, usable(base.r, 0.8F)), std::max(0.0F, usable(base.g, 0.8F)), std::max(0.0F, usable(base.b, 0.8F))};
    LinearMaterial material{LinearRgb{}, colour * (1.0F - metallic), LinearRgb{}, std::nullopt};
    const float alpha = roughness * roughness;
    if (pbr && alpha < 0.95F) {
        const float f0 = 0.04F * (1.0F - metallic);
        material.specular = LinearRgb{f0, f0, f0} + colour * metallic;
        material.shininess = std::min(2.0F / std::max(alpha * alpha, 1e-4F) - 2.0F, 2048.0F);
    }
    return material;
}

// How a format writes vertex colours: glTF's COLOR_0 is linear; PLY and STL colours are the
// bytes a screen shows, sRGB (doc/conventions.md#vertex-colours).
enum class ColourSpace { linear, srgb };

ColourSpace colour_space_of(std::string format) {
    std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (format.starts_with(".")) format.erase(0, 1);
    return format == "ply" || format == "stl" ? ColourSpace::srgb : ColourSpace::linear;
}

// A file's colour channel in linear light: clamped to [0, 1], white where it is not a number.
float linear_channel(float written, ColourSpace space) {
    const float c = std::isfinite(written) ? std::clamp(written, 0.0F, 1.0F) : 1.0F;
    return space == ColourSpace::srgb ? static_cast<float>(linear_from_srgb_channel(c)) : c;
}

class SceneReader {
public:
    SceneReader(const aiScene& scene, const std::filesystem::path& path, ColourSpace colours, const ObjOptions& options, Model& model)
        : scene_(scene), path_(path), name_(printable(path.string())), colours_(colours), options_(options), model_(model) {}

    detail::PolygonSoup soup() {
        if (scene_.mRootNode == nullptr) throw std::runtime_error("it holds no scene");
        visit(*scene_.mRootNode, glm::dmat4(1.0), 0);
        return std::move(soup_);
    }

    // Each material's colour and diffuse map; a map that cannot be read is a warning.
    std::vector<std::pair<LinearMaterial, std::shared_ptr<const Texture>>> materials() {
        std::vector<std::pair<LinearMaterial, std::shared_ptr<const Texture>>> out;
        for (unsigned i = 0; i < scene_.mNumMaterials; ++i) {
            const aiMaterial& m = *scene_.mMaterials[i];
            out.emplace_back(material_from(m), options_.load_textures ? map_of(m) : nullptr);
        }
        return out;
    }

private:
    void visit(const aiNode& node, const glm::dmat4& parent, int depth) {
        if (depth > detail::kMaxGltfNodeDepth) throw std::runtime_error("its nodes nest more than " + std::to_string(detail::kMaxGltfNodeDepth) + " deep (or loop)");
        if (!on_path_.insert(&node).second) throw std::runtime_error("its node hierarchy loops");
        const glm::dmat4 world = parent * matrix_of(node.mTransformation);
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes[i] >= scene_.mNumMeshes) throw std::runtime_error("a node names mesh " + std::to_string(node.mMeshes[i]) + ", which it lacks");
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
        const auto first = static_cast<std::int64_t>(soup_.positions.size());
        const bool has_normals = mesh.mNormals != nullptr, has_uvs = mesh.mTextureCoords[0] != nullptr;
        const bool has_colours = mesh.mColors[0] != nullptr;
        // Normals, texture coordinates and colours are kept one per position: meshes without them pad.
        if (has_normals) soup_.normals.resize(soup_.positions.size(), glm::vec3(0.0F));
        if (has_uvs) soup_.uvs.resize(soup_.positions.size(), glm::vec2(0.0F));
        if (has_colours) soup_.colours.resize(soup_.positions.size(), LinearRgb{1.0F, 1.0F, 1.0F});
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            if (!finite(p)) throw std::runtime_error("mesh '" + printable(mesh.mName.C_Str(), 80) + "' has a vertex that is not a finite point");
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
            if (has_colours) {  // alpha is not drawn: surfaces are opaque
                const aiColor4D& c = mesh.mColors[0][v];
                soup_.colours.push_back({linear_channel(c.r, colours_), linear_channel(c.g, colours_), linear_channel(c.b, colours_)});
            }
        }
        std::vector<glm::dvec3> outline;
        std::vector<detail::SoupCorner> corners;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices < 3) continue;  // points and lines draw nothing
            if (face.mNumIndices > kMaxFaceCorners) throw std::runtime_error("a face of more than " + std::to_string(kMaxFaceCorners) + " corners");
            outline.clear();
            corners.clear();
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const unsigned index = face.mIndices[k];
                if (index >= mesh.mNumVertices) {
                    throw std::runtime_error("a face names vertex " + std::to_string(index) + " of a mesh of " + std::to_string(mesh.mNumVertices));
                }
                const std::int64_t at = first + index;
                corners.push_back({at, has_normals ? at : detail::kNoIndex, has_uvs ? at : detail::kNoIndex, has_colours ? at : detail::kNoIndex});
                outline.emplace_back(soup_.positions[static_cast<std::size_t>(at)]);
            }
            for (const auto& [a, b, c] : detail::triangles_of_polygon(outline)) {
                soup_.triangles.push_back({{corners[a], corners[c], corners[b]}, static_cast<int>(mesh.mMaterialIndex)});
            }
        }
        if (!soup_.normals.empty()) soup_.normals.resize(soup_.positions.size(), glm::vec3(0.0F));
        if (!soup_.uvs.empty()) soup_.uvs.resize(soup_.positions.size(), glm::vec2(0.0F));
        if (!soup_.colours.empty()) soup_.colours.resize(soup_.positions.size(), LinearRgb{1.0F, 1.0F, 1.0F});
    }

    std::shared_ptr<const Texture> map_of(const aiMaterial& m) {
        aiString written;
        if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &written) != AI_SUCCESS && m.GetTexture(aiTextureType_DIFFUSE, 0, &written) != AI_SUCCESS) {
            return nullptr;
        }
        const std::string text = written.C_Str();
        const auto known = loaded_.find(text);
        if (known != loaded_.end()) return known->second;
        std::shared_ptr<const Texture> texture;
        try {
            if (const aiTexture* embedded = scene_.GetEmbeddedTexture(written.C_Str())) {
                if (embedded->mHeight != 0) throw std::runtime_error("an embedded image of raw texels, which raster does not read");
                const auto* bytes = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
                texture = std::make_shared<const Texture>(decode_texture({bytes, embedded->mWidth}, options_.max_texels));
            } else {
                const std::filesystem::path file = detail::resolve_named_path(path_.parent_path(), text, options_.confine);
                if (FileIdentity identity; identity_of(file, identity)) model_.sources.push_back({file, identity, "texture"});
                texture = std::make_shared<const Texture>(read_texture(file, options_.max_texels, options_.confine, &model_.sources));
            }
        } catch (const std::runtime_error& problem) {
            model_.warnings.push_back(name_ + ": texture '" + printable(text, 80) + "': " + problem.what() + "; drawing its material's colour");
        }
        loaded_.emplace(text, texture);
        return texture;
    }

    const aiScene& scene_;
    std::filesystem::path path_;
    std::string name_;
    ColourSpace colours_;
    const ObjOptions& options_;
    Model& model_;
    detail::PolygonSoup soup_;
    std::unordered_set<const aiNode*> on_path_;
    std::map<std::string, std::shared_ptr<const Texture>> loaded_;
};

// The model of a scene assimp read; `path` places the files it names and `name` is for messages.
void model_from_scene(const aiScene& scene, const std::filesystem::path& path, const std::string& name, ColourSpace colours,
                      const ObjOptions& options, Model& model) {
    try {
        SceneReader reader(scene, path, colours, options, model);
        detail::PolygonSoup soup = reader.soup();
        const auto materials = reader.materials();
        for (auto& [id, mesh] : detail::meshes_by_material(soup, options.crease_degrees)) {
            ModelPart part{"", std::move(mesh), default_model_material()};
            if (id >= 0 && static_cast<std::size_t>(id) < materials.size()) {
                const aiString material_name = scene.mMaterials[id]->GetName();
                part.material_name = material_name.C_Str();
                part.material = materials[static_cast<std::size_t>(id)].first;
                if (!part.mesh.uvs.empty()) part.texture = materials[static_cast<std::size_t>(id)].second;
            }
            model.parts.push_back(std::move(part));
        }
    } catch (const std::runtime_error& problem) {
        throw std::runtime_error(name + ": " + problem.what());
    }
    if (model.parts.empty()) throw std::runtime_error(name + ": no faces to draw");
}

bool readable(const aiScene* scene) { return scene != nullptr && (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) == 0; }

constexpr const char* kUnreadable = "not a glTF 2.0, STL or PLY model raster can read (or one it finds broken)";

}  // namespace

Model read_scene_file(const std::filesystem::path& path, const ObjOptions& options) {
    const std::string name = printable(path.string());
    Model model;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;  // outlives the importer that gave them up
    Assimp::Importer importer;
    removed = keep_only_reader(importer, extension);
    auto* files = new BoundedFiles(options, model.sources, path, extension);  // the importer owns it
    importer.SetIOHandler(files);
    if (FileIdentity identity; !identity_of(path, identity)) {
        // assimp would stop at its own existence check, giving no reason: InputFile gives one.
        if (Assimp::IOStream* stream = files->Open(path.c_str(), "rb")) files->Close(stream);
        throw std::runtime_error(name + ": " + (files->first_reason().empty() ? kUnreadable : files->first_reason()));
    }
    // Our own checks follow; assimp's validation refuses indices out of range and broken arrays.
    const aiScene* scene = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
    if (!readable(scene)) {
        const std::string& why = files->first_failure();
        if (why.starts_with("'" + name + "' ")) throw std::runtime_error(name + ": " + files->first_reason());  // the model itself
        throw std::runtime_error(name + ": " + (why.empty() ? kUnreadable : why));
    }
    model_from_scene(*scene, path, name, colour_space_of(extension), options, model);
    return model;
}

Model parse_scene_file(std::span<const std::uint8_t> bytes, const std::string& format, const ObjOptions& options) {
    const std::string name = "<memory>";
    Model model;
    ObjOptions no_files = options;
    no_files.load_textures = false;
    no_files.confine = "/nonexistent-raster-memory-only";  // a buffer or image the text names is never opened
    std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;
    Assimp::Importer importer;
    removed = keep_only_reader(importer, "." + format);
    importer.SetIOHandler(new BoundedFiles(no_files, model.sources));
    if (std::string problem = structure_problem(bytes, "." + format, "", no_files); !problem.empty()) throw std::runtime_error(name + ": " + problem);
    const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_ValidateDataStructure, format.c_str());
    if (!readable(scene)) throw std::runtime_error(name + ": " + kUnreadable);
    model_from_scene(*scene, "", name, colour_space_of(format), no_files, model);
    return model;
}

}  // namespace raster
