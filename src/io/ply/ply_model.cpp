// A PLY body as raster's Model: a point cloud straight into its mesh's arrays, faces through the
// builder that splits, re-winds and smooths every format's faces (doc/conventions.md#ply-reader).
#include "io/ply/ply_model.hpp"

#include "geometry/polygon_triangles.hpp"
#include "io/for_each_index.hpp"
#include "io/model_builder.hpp"
#include "io/vertex_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <glm/vec3.hpp>

namespace raster::detail {
namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The material assimp's PLY reader gave every PLY, as raster read it: white, no highlight.
ModelPart ply_part(Mesh mesh) {
    return ModelPart{"", std::move(mesh), LinearMaterial{LinearRgb{}, LinearRgb{1.0F, 1.0F, 1.0F}, LinearRgb{}, {}}};
}

// A body read with its vertices in place (faces were declared, none read): the finite ones only.
void drop_non_finite(PlyBody& body) {
    std::size_t kept = 0;
    for (std::size_t v = 0; v < body.positions.size(); ++v) {
        if (!finite(body.positions[v])) continue;
        body.positions[kept] = body.positions[v];
        if (!body.normals.empty()) body.normals[kept] = unit_or_zero(body.normals[v]);
        if (!body.uvs.empty()) body.uvs[kept] = body.uvs[v];
        if (!body.colours.empty()) body.colours[kept] = body.colours[v];
        if (!body.alphas.empty()) body.alphas[kept] = body.alphas[v];
        ++kept;
    }
    body.positions.resize(kept);
    if (!body.normals.empty()) body.normals.resize(kept);
    if (!body.uvs.empty()) body.uvs.resize(kept);
    if (!body.colours.empty()) body.colours.resize(kept);
    if (!body.alphas.empty()) body.alphas.resize(kept);
}

// Every vertex a point of one mesh, in the file's order: the arrays are the mesh's own.
void add_cloud(PlyBody& body, Model& model, std::size_t& unplaced) {
    if (body.places_kept) drop_non_finite(body);
    unplaced = body.non_finite;
    if (body.positions.empty()) return;
    Mesh mesh;
    const std::size_t n = body.positions.size();
    mesh.positions = std::move(body.positions);
    mesh.normals = std::move(body.normals);
    mesh.normals.resize(n, glm::vec3(0.0F));  // a point without a normal is drawn unlit
    mesh.uvs = std::move(body.uvs);
    mesh.colours = std::move(body.colours);
    mesh.alphas = std::move(body.alphas);
    mesh.points.resize(n);
    std::iota(mesh.points.begin(), mesh.points.end(), std::uint32_t{0});
    model.parts.push_back(ply_part(std::move(mesh)));
}

// Faces as assimp's reader gave them to raster's scene reader: one corner of one vertex, faces
// of one corner points, of two lines, of more split into triangles re-wound for raster's world.
void add_faces(PlyBody& body, const std::string& name, const ObjOptions& options, Model& model, std::size_t& unplaced) {
    PolygonSoup soup;
    const bool normals = !body.normals.empty(), uvs = !body.uvs.empty(), colours = !body.colours.empty();
    soup.positions = std::move(body.positions);
    soup.normals = std::move(body.normals);
    soup.uvs = std::move(body.uvs);
    soup.colours = std::move(body.colours);
    soup.alphas = std::move(body.alphas);
    if (soup.positions.size() >= kMaxSoupVertices)
        throw std::runtime_error("more vertices than raster indexes in 32 bits");
    const auto corner_at = [&](std::uint32_t at) {
        return SoupCorner{at, normals ? at : kNoIndex, uvs ? at : kNoIndex, colours ? at : kNoIndex, kNoIndex};
    };
    const auto drawable = [&](const SoupCorner& corner) {
        if (finite(soup.positions[static_cast<std::size_t>(corner.position)])) return true;
        ++unplaced;
        return false;
    };
    soup.triangles.reserve(body.corners.size());
    std::vector<glm::dvec3> outline;
    std::vector<SoupCorner> corners;
    for (std::size_t f = 0; f < body.face_starts.size(); ++f) {
        const auto first = static_cast<std::size_t>(body.face_starts[f]);
        const std::size_t end =
            f + 1 < body.face_starts.size() ? static_cast<std::size_t>(body.face_starts[f + 1]) : body.corners.size();
        const std::span<const std::uint32_t> face(body.corners.data() + first, end - first);
        if (face.size() == 1) {
            if (const SoupCorner corner = corner_at(face[0]); drawable(corner)) soup.points.push_back({corner, 0});
            continue;
        }
        if (face.size() == 2) {
            const SoupCorner a = corner_at(face[0]), b = corner_at(face[1]);
            if (drawable(a) && drawable(b)) soup.segments.push_back({{a, b}, 0});
            continue;
        }
        outline.clear();
        corners.clear();
        for (const std::uint32_t index : face) {
            corners.push_back(corner_at(index));
            outline.emplace_back(soup.positions[index]);
            if (!std::isfinite(outline.back().x)) {
                throw std::runtime_error(name + ": face " + std::to_string(f + 1) + " uses vertex " +
                                         std::to_string(index) + ", whose position is not a finite point");
            }
        }
        for (const auto& [a, b, c] : triangles_of_polygon(outline))
            soup.triangles.push_back({{corners[a], corners[c], corners[b]}, 0});
    }
    for (auto& [id, mesh] : meshes_by_material(soup, options.crease_degrees, threads_or_cores(options.threads)))
        model.parts.push_back(ply_part(std::move(mesh)));
}

}  // namespace

void model_from_ply(PlyBody body, const std::string& name, const ObjOptions& options, Model& model) {
    std::size_t unplaced = 0;  // points and line ends skipped for coordinates that are not finite
    if (body.face_starts.empty()) {
        add_cloud(body, model, unplaced);
    } else {
        add_faces(body, name, options, model, unplaced);
    }
    if (unplaced > 0) {
        model.warnings.push_back(name + ": skipped " + std::to_string(unplaced) +
                                 " points or line ends that are not finite points");
    }
    if (model.parts.empty()) {
        if (!body.cut_short.empty()) throw std::runtime_error(name + ": " + body.cut_short);
        if (body.declared_vertices == 0)
            throw std::runtime_error(name + ": " + kNothingToDraw + " (its header declares no vertices)");
        throw std::runtime_error(name + ": " + kNothingToDraw);
    }
    if (!body.cut_short.empty()) model.warnings.push_back(name + ": " + body.cut_short + "; drawing what is there");
    warn_of_vertex_alphas(name, body.unreadable_alphas, model.warnings);
    bool points_lose_alpha = false;
    for (ModelPart& part : model.parts) {
        const bool translucent =
            std::any_of(part.mesh.alphas.begin(), part.mesh.alphas.end(), [](float a) { return a < 1.0F; });
        const bool loose = !part.mesh.points.empty() || !part.mesh.segments.empty();
        points_lose_alpha = points_lose_alpha || (translucent && loose);
        settle_vertex_alphas(part, false);
    }
    // Points and lines are drawn opaque (doc/conventions.md#vertex-alpha): said, not dropped silently.
    if (points_lose_alpha)
        model.warnings.push_back(name + ": points and lines are drawn opaque; their vertex alpha is not drawn");
}

}  // namespace raster::detail
