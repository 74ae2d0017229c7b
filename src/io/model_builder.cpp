#include "io/model_builder.hpp"

#include "io/for_each_index.hpp"
#include "io/vertex_ids.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <span>
#include <glm/geometric.hpp>

namespace raster::detail {

namespace {

// Twice the area times the outward unit normal, as (b - a) x (c - b) is in raster's world; in
// double, where neither huge nor tiny float coordinates overflow or vanish.
glm::dvec3 area_normal(const PolygonSoup& soup, const SoupTriangle& triangle) {
    const glm::dvec3 a = soup.positions[static_cast<std::size_t>(triangle.corners[0].position)];
    const glm::dvec3 b = soup.positions[static_cast<std::size_t>(triangle.corners[1].position)];
    const glm::dvec3 c = soup.positions[static_cast<std::size_t>(triangle.corners[2].position)];
    return glm::cross(b - a, c - b);
}

// The unit vector along v in float, or zero when v has no length or is not finite.
glm::vec3 unit_of(glm::dvec3 v) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::vec3(0.0F);
    return glm::vec3(v / length);
}

// Triangles a thread takes at once, and blocks whose corner normals are held before their vertices are found.
constexpr std::size_t kBlock = std::size_t{1} << 14;
constexpr std::size_t kBlocksAtOnce = 16;

std::size_t blocks_of(std::size_t triangles) { return (triangles + kBlock - 1) / kBlock; }

// Beyond this many facets around one position, its corners keep their facets' normals: the
// smoothing compares every pair, and a fan of thousands would take quadratic time.
constexpr std::size_t kMaxSmoothedNeighbours = 64;

// Which of the optional per-vertex arrays a material's mesh has: any corner of it that has one gives it to all.
struct VertexArrays {
    bool uvs = false, colours = false, tangents = false;
};

std::uint32_t bits_of(float value) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

// The file's unit normal at a corner, or zero when it has none or a broken one.
glm::vec3 file_normal(const PolygonSoup& soup, const SoupCorner& corner) {
    return corner.normal != kNoIndex ? unit_or_zero(soup.normals[static_cast<std::size_t>(corner.normal)])
                                     : glm::vec3(0.0F);
}

// Appends the corner's position, `normal`, and its texture coordinate, colour and tangent when the mesh has them.
void push_vertex(Mesh& mesh, const PolygonSoup& soup, const SoupCorner& corner, glm::vec3 normal, VertexArrays with) {
    mesh.positions.push_back(soup.positions[static_cast<std::size_t>(corner.position)]);
    mesh.normals.push_back(normal);
    if (with.uvs)
        mesh.uvs.push_back(corner.uv != kNoIndex ? soup.uvs[static_cast<std::size_t>(corner.uv)] : glm::vec2(0.0F));
    // A corner without a colour in a part with colours shows the material as it is.
    if (with.colours) {
        mesh.colours.push_back(corner.colour != kNoIndex ? soup.colours[static_cast<std::size_t>(corner.colour)]
                                                         : LinearRgb{1.0F, 1.0F, 1.0F});
        if (!soup.alphas.empty()) {
            const auto at = static_cast<std::size_t>(corner.colour);
            mesh.alphas.push_back(corner.colour != kNoIndex && at < soup.alphas.size() ? soup.alphas[at] : 1.0F);
        }
    }
    if (with.tangents) {  // zero where a corner has none: the shader then falls back to the cotangent frame
        mesh.tangents.push_back(corner.tangent != kNoIndex ? soup.tangents[static_cast<std::size_t>(corner.tangent)]
                                                           : glm::vec4(0.0F));
    }
}

}  // namespace

void add_every_vertex_as_a_point(PolygonSoup& soup) {
    const bool paired = soup.normals.size() == soup.positions.size();
    const bool coloured = soup.colours.size() == soup.positions.size();
    soup.points.reserve(soup.points.size() + soup.positions.size());
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        const glm::vec3& p = soup.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
        const auto at = static_cast<std::uint32_t>(v);  // fewer than kMaxSoupVertices, as every reader checks
        soup.points.push_back({{at, paired ? at : kNoIndex, kNoIndex, coloured ? at : kNoIndex}, -1});
    }
}

std::vector<std::pair<int, Mesh>> meshes_by_material(const PolygonSoup& soup, double crease_degrees,
                                                     std::size_t threads) {
    // Facet normals, and the facets around each position (in facet order, counted then filled,
    // with no list allocated for each position), for the normals the file lacks.
    const std::size_t triangles = soup.triangles.size();
    std::vector<double> twice_area(triangles);  // the area normal's length: all the smoothing weighs by
    std::vector<glm::vec3> unit(triangles);
    for_each_index(blocks_of(triangles), threads, [&](std::size_t block) {
        for (std::size_t t = block * kBlock; t < std::min(triangles, (block + 1) * kBlock); ++t) {
            const glm::dvec3 weighted = area_normal(soup, soup.triangles[t]);
            twice_area[t] = glm::length(weighted);
            unit[t] = unit_of(weighted);
        }
    });
    std::vector<std::size_t> first_around(soup.positions.size() + 1, 0);
    for (std::size_t t = 0; t < triangles; ++t) {
        if (unit[t] == glm::vec3(0.0F)) continue;
        for (const SoupCorner& corner : soup.triangles[t].corners)
            ++first_around[static_cast<std::size_t>(corner.position) + 1];
    }
    for (std::size_t p = 1; p < first_around.size(); ++p) first_around[p] += first_around[p - 1];
    std::vector<std::uint32_t> around(first_around.back());
    std::vector<std::size_t> filled(first_around.begin(), first_around.end() - 1);
    for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
        if (unit[t] == glm::vec3(0.0F)) continue;
        for (const SoupCorner& corner : soup.triangles[t].corners)
            around[filled[static_cast<std::size_t>(corner.position)]++] = static_cast<std::uint32_t>(t);
    }
    filled = {};
    const auto cos_crease = static_cast<float>(std::cos(crease_degrees * std::numbers::pi / 180.0));
    const auto generated_normal = [&](std::size_t t, std::int64_t position) {
        const auto p = static_cast<std::size_t>(position);
        const std::span<const std::uint32_t> neighbours(around.data() + first_around[p],
                                                        first_around[p + 1] - first_around[p]);
        if (crease_degrees <= 0.0 || neighbours.size() > kMaxSmoothedNeighbours) return unit[t];
        glm::dvec3 sum(0.0);
        for (const std::uint32_t other : neighbours) {
            // Area-weighted; in double, which float coordinates cannot overflow.
            if (glm::dot(unit[other], unit[t]) >= cos_crease) sum += glm::dvec3(unit[other]) * twice_area[other];
        }
        const glm::vec3 mean = unit_of(sum);
        return mean == glm::vec3(0.0F) ? unit[t] : mean;
    };

    std::map<int, Mesh> meshes;
    VertexIds vertices(soup.positions.size());
    std::map<int, VertexArrays> arrays;
    const auto note_corner = [&](const SoupCorner& corner, int material) {
        VertexArrays& with = arrays[material];
        with.uvs = with.uvs || corner.uv != kNoIndex;
        with.colours = with.colours || corner.colour != kNoIndex;
        with.tangents = with.tangents || corner.tangent != kNoIndex;
    };
    for (const SoupTriangle& triangle : soup.triangles) {
        for (const SoupCorner& corner : triangle.corners) note_corner(corner, triangle.material);
    }
    for (const SoupPoint& point : soup.points) note_corner(point.corner, point.material);
    for (const SoupSegment& segment : soup.segments) {
        for (const SoupCorner& end : segment.ends) note_corner(end, segment.material);
    }
    // A vertex of `material`'s mesh with `normal`: shared with any other corner that has all its
    // attributes. The last material's mesh, ids and arrays are kept: files give faces in runs.
    struct Looked {
        int material = 0;
        Mesh* mesh = nullptr;
        VertexArrays with;
    } last;
    const auto vertex_of = [&](const SoupCorner& corner, glm::vec3 normal, int material) {
        if (last.mesh == nullptr || last.material != material) last = {material, &meshes[material], arrays[material]};
        const VertexKey key{corner.position, bits_of(normal.x), bits_of(normal.y), bits_of(normal.z),
                            corner.uv,       corner.colour,     corner.tangent};
        const auto [id, added] =
            vertices.find_or_add(material, key, static_cast<std::uint32_t>(last.mesh->positions.size()));
        if (added) push_vertex(*last.mesh, soup, corner, normal, last.with);
        return id;
    };
    // Each corner's normal is worked out on every thread a block at a time; the vertices are then found in order.
    std::vector<std::array<glm::vec3, 3>> normals(std::min(triangles, kBlock * kBlocksAtOnce));
    for (std::size_t start = 0; start < triangles; start += normals.size()) {
        const std::size_t end = std::min(triangles, start + normals.size());
        for_each_index(blocks_of(end - start), threads, [&](std::size_t block) {
            for (std::size_t t = start + block * kBlock; t < std::min(end, start + (block + 1) * kBlock); ++t) {
                if (unit[t] == glm::vec3(0.0F)) continue;
                for (std::size_t k = 0; k < 3; ++k) {
                    const SoupCorner& corner = soup.triangles[t].corners[k];
                    glm::vec3 normal(0.0F);  // the file's, unless it has none or a zero or broken one
                    if (corner.normal != kNoIndex)
                        normal = unit_or_zero(soup.normals[static_cast<std::size_t>(corner.normal)]);
                    normals[t - start][k] = normal == glm::vec3(0.0F) ? generated_normal(t, corner.position) : normal;
                }
            }
        });
        for (std::size_t t = start; t < end; ++t) {
            if (unit[t] == glm::vec3(0.0F)) continue;  // no area: it could never cover a pixel
            const SoupTriangle& triangle = soup.triangles[t];
            Facet facet{{}, unit[t]};
            for (std::size_t k = 0; k < 3; ++k)
                facet.corners[k] = vertex_of(triangle.corners[k], normals[t - start][k], triangle.material);
            last.mesh->facets.push_back(facet);
        }
    }
    // Every point is a vertex of its own: a cloud of millions would only slow a shared index down.
    // Its arrays are sized once, so that they are never copied as they grow.
    std::map<int, std::size_t> cloud_sizes;
    for (std::size_t i = 0, j = 0; i < soup.points.size(); i = j) {  // by runs: a cloud is one
        while (j < soup.points.size() && soup.points[j].material == soup.points[i].material) ++j;
        cloud_sizes[soup.points[i].material] += j - i;
    }
    for (const auto& [material, count] : cloud_sizes) {
        Mesh& mesh = meshes[material];
        const VertexArrays with = arrays[material];
        const std::size_t size = mesh.positions.size() + count;
        mesh.positions.reserve(size);
        mesh.normals.reserve(size);
        if (with.uvs) mesh.uvs.reserve(size);
        if (with.colours) mesh.colours.reserve(size);
        if (with.tangents) mesh.tangents.reserve(size);
        mesh.points.reserve(mesh.points.size() + count);
    }
    Mesh* cloud = nullptr;  // the last point's mesh: a cloud of one material looks it up once
    int cloud_material = 0;
    VertexArrays with;
    for (const SoupPoint& point : soup.points) {
        if (cloud == nullptr || point.material != cloud_material) {
            cloud_material = point.material;
            cloud = &meshes[cloud_material];
            with = arrays[cloud_material];
        }
        cloud->points.push_back(static_cast<std::uint32_t>(cloud->positions.size()));
        push_vertex(*cloud, soup, point.corner, file_normal(soup, point.corner), with);
    }
    for (const SoupSegment& segment : soup.segments) {
        const std::uint32_t a = vertex_of(segment.ends[0], file_normal(soup, segment.ends[0]), segment.material);
        const std::uint32_t b = vertex_of(segment.ends[1], file_normal(soup, segment.ends[1]), segment.material);
        meshes[segment.material].segments.push_back({a, b});
    }
    std::vector<std::pair<int, Mesh>> result;
    for (auto& [material, mesh] : meshes) {
        if (std::all_of(mesh.alphas.begin(), mesh.alphas.end(), [](float a) { return a >= 1.0F; })) mesh.alphas = {};
        result.emplace_back(material, std::move(mesh));
    }
    return result;
}

}  // namespace raster::detail
