// glTF 2.0, STL and PLY read by the Open Asset Import Library, one reader per format, every file
// through BoundedFiles; src/io/assimp/ is the only folder that includes assimp.
#include <raster/io/model_file.hpp>

#include "io/assimp/bounded_files.hpp"
#include "io/assimp/scene_model.hpp"
#include "io/model_format.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cctype>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>
#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace raster {

namespace {

using detail::BoundedFiles;

// Leaves `importer` only the reader of one format: when it declines a file, assimp would
// otherwise offer it to every reader it has (3DS, FBX, Collada, ...). Returns those taken out,
// which the caller now owns.
std::vector<std::unique_ptr<Assimp::BaseImporter>> keep_only_reader(Assimp::Importer& importer,
                                                                    const std::string& extension) {
    const std::string wanted = extension == ".glb" ? "glb" : extension.substr(1);
    std::vector<Assimp::BaseImporter*> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        const aiImporterDesc* about = importer.GetImporterInfo(i);
        const std::string name = about != nullptr && about->mName != nullptr ? about->mName : "";
        const std::string endings = about != nullptr && about->mFileExtensions != nullptr
                                        ? " " + std::string(about->mFileExtensions) + " "
                                        : "";
        const bool gltf2 = name.find("glTF2") != std::string::npos;
        const bool keep =
            endings.find(" " + wanted + " ") != std::string::npos && (wanted.starts_with("gl") ? gltf2 : true);
        if (!keep) others.push_back(importer.GetImporter(i));
    }
    std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;
    for (Assimp::BaseImporter* other : others) {
        if (importer.UnregisterLoader(other) == AI_SUCCESS) removed.emplace_back(other);
    }
    return removed;
}

bool readable(const aiScene* scene) { return scene != nullptr && (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) == 0; }

// The scene the importer read, once assimp's validation passes it (it refuses indices out of
// range and broken arrays). Validation also refuses a mesh without faces, which is how assimp's
// PLY reader gives a point cloud: each such mesh holds one point while it runs, and none after.
const aiScene* validated(Assimp::Importer& importer) {
    auto* scene = const_cast<aiScene*>(importer.GetScene());  // the importer's own, not yet handed out
    if (scene == nullptr) return nullptr;
    std::vector<aiMesh*> clouds;
    for (unsigned i = 0; scene->mMeshes != nullptr && i < scene->mNumMeshes; ++i) {
        aiMesh* mesh = scene->mMeshes[i];
        if (mesh == nullptr || mesh->mNumFaces != 0 || mesh->mFaces != nullptr || mesh->mNumVertices == 0) continue;
        mesh->mFaces = new aiFace[1];
        mesh->mFaces[0].mNumIndices = 1;
        mesh->mFaces[0].mIndices = new unsigned[1]{0};
        mesh->mNumFaces = 1;
        mesh->mPrimitiveTypes |= aiPrimitiveType_POINT;
        clouds.push_back(mesh);
    }
    scene = const_cast<aiScene*>(importer.ApplyPostProcessing(aiProcess_ValidateDataStructure));
    if (scene == nullptr) return nullptr;
    for (aiMesh* mesh : clouds) {
        delete[] mesh->mFaces;
        mesh->mFaces = nullptr;
        mesh->mNumFaces = 0;
    }
    return scene;
}

// Why assimp read nothing, in its reader's name: "not a Collada model raster can read (...)".
std::string unreadable(const std::string& extension) {
    const bool gltf = extension == ".gltf" || extension == ".glb";
    const std::filesystem::path named = "model" + extension;
    const std::string format = gltf ? "glTF 2.0" : detail::format_name(detail::model_format_of(named), named);
    return "not " + detail::a_model(format) + " raster can read (or one it finds broken)";
}

// Why assimp read nothing from a PLY that passed raster's checks: cut short, or declaring no vertices.
std::string ply_refusal(const detail::PlyShape& shape) {
    if (!shape.cut_short.empty()) return shape.cut_short;
    if (shape.vertices == 0) return std::string(kNothingToDraw) + " (its header declares no vertices)";
    return unreadable(".ply");
}

}  // namespace

namespace detail {

bool assimp_claims(const std::string& ending) {
    if (ending.size() < 2 || ending[0] != '.') return false;
    const Assimp::Importer importer;
    return importer.IsExtensionSupported(ending);
}

}  // namespace detail

Model read_scene_file(const std::filesystem::path& path, const ObjOptions& options) {
    const std::string name = printable(path.string());
    Model model;
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::vector<std::unique_ptr<Assimp::BaseImporter>> removed;  // outlives the importer that gave them up
    Assimp::Importer importer;
    removed = keep_only_reader(importer, extension);
    auto* files = new BoundedFiles(options, model.sources, path, extension);  // the importer owns it
    importer.SetIOHandler(files);
    if (FileIdentity identity; !identity_of(path, identity)) {
        // assimp would stop at its own existence check, giving no reason: InputFile gives one.
        if (Assimp::IOStream* stream = files->Open(path.c_str(), "rb")) files->Close(stream);
        throw std::runtime_error(name + ": " +
                                 (files->first_reason().empty() ? unreadable(extension) : files->first_reason()));
    }
    // Our own checks follow validation's.
    importer.ReadFile(path.string(), 0);
    const aiScene* scene = validated(importer);
    if (!readable(scene)) {
        const std::string& why = files->first_failure();
        if (why.starts_with("'" + name + "' "))
            throw std::runtime_error(name + ": " + files->first_reason());  // the model itself
        if (why.empty() && extension == ".ply") throw std::runtime_error(name + ": " + ply_refusal(files->ply_shape()));
        throw std::runtime_error(name + ": " + (why.empty() ? unreadable(extension) : why));
    }
    detail::model_from_scene(*scene, path, name, detail::colour_space_of(extension), options, model,
                             &files->gltf_facts());
    if (!files->ply_shape().cut_short.empty())
        model.warnings.push_back(name + ": " + files->ply_shape().cut_short + "; drawing what is there");
    detail::warn_of_unsupported_extensions(files->gltf_facts().extensions, name, model);
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
    detail::GltfFacts facts;
    if (std::string problem = detail::structure_problem(bytes, "." + format, "", no_files, nullptr, &facts);
        !problem.empty())
        throw std::runtime_error(name + ": " + problem);
    importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, format.c_str());
    const aiScene* scene = validated(importer);
    if (!readable(scene)) throw std::runtime_error(name + ": " + unreadable("." + format));
    detail::model_from_scene(*scene, "", name, detail::colour_space_of(format), no_files, model, &facts);
    return model;
}

}  // namespace raster
