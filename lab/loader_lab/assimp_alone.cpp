// assimp alone, with the product's flags, its scene walked as a program using it must walk it.
#include "loader_lab/loaders.hpp"

#include <set>
#include <string>
#include <vector>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/mat4x4.hpp>

namespace loader_lab {
namespace {

glm::dmat4 matrix_of(const aiMatrix4x4& m) {
    glm::dmat4 out(1.0);
    for (unsigned row = 0; row < 4; ++row) {
        for (unsigned column = 0; column < 4; ++column)
            out[static_cast<int>(column)][static_cast<int>(row)] = m[row][column];
    }
    return out;
}

void walk_assimp(const aiScene& scene, const aiNode& node, const glm::dmat4& parent, int depth, Reading& r,
                 std::set<unsigned>& used) {
    if (depth > kMaxNodeDepth)
        throw WalkError("nodes nest more than " + std::to_string(kMaxNodeDepth) + " deep (or loop)");
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

}  // namespace

Reading by_assimp(const fs::path& path) {
    Assimp::Importer importer;
    // The product's flags (src/io/assimp/scene_file.cpp): validation only, no triangulation or merging.
    const aiScene* scene = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
    if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0)
        throw std::runtime_error(importer.GetErrorString());
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
        if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &map) != AI_SUCCESS &&
            m.GetTexture(aiTextureType_DIFFUSE, 0, &map) != AI_SUCCESS)
            continue;
        if (scene->GetEmbeddedTexture(map.C_Str()) != nullptr || exists_quietly(path.parent_path() / map.C_Str()))
            maps.insert(map.C_Str());
    }
    r.textures = maps.size();
    return r;
}

}  // namespace loader_lab
