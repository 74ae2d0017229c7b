#include <raster/io/model.hpp>

#include <cstring>
#include <unordered_map>

namespace raster {

namespace {

// A corner's position by its bits: parts split a vertex by normal and texture coordinate, but a
// seam between them is still closed where the positions are the same.
struct PointKey {
    std::uint32_t x, y, z;
    friend bool operator==(const PointKey&, const PointKey&) = default;
};

PointKey key_of(glm::vec3 p) {
    PointKey key{};
    std::memcpy(&key.x, &p.x, 4);
    std::memcpy(&key.y, &p.y, 4);
    std::memcpy(&key.z, &p.z, 4);
    return key;
}

struct EdgeKey {
    PointKey from, to;  // `from` the lesser, so both directions share a key
    friend bool operator==(const EdgeKey&, const EdgeKey&) = default;
};

struct EdgeHash {
    std::size_t operator()(const EdgeKey& e) const noexcept {
        std::size_t h = 1469598103934665603ULL;
        for (const std::uint32_t word : {e.from.x, e.from.y, e.from.z, e.to.x, e.to.y, e.to.z})
            h = (h ^ word) * 1099511628211ULL;
        return h;
    }
};

bool less(const PointKey& a, const PointKey& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

}  // namespace

std::vector<bool> open_parts(const Model& model) {
    // Each edge's uses one way minus the other, over the whole model: a closed, consistently
    // wound surface leaves 0 on every edge, however its parts divide it.
    std::unordered_map<EdgeKey, long, EdgeHash> balance;
    const auto for_each_edge = [](const ModelPart& part, const auto& visit) {
        for (const Facet& facet : part.mesh.facets) {
            for (std::size_t k = 0; k < 3; ++k) {
                const PointKey a = key_of(part.mesh.positions[facet.corners[k]]);
                const PointKey b = key_of(part.mesh.positions[facet.corners[(k + 1) % 3]]);
                visit(less(a, b) ? EdgeKey{a, b} : EdgeKey{b, a}, less(a, b) ? 1 : -1);
            }
        }
    };
    for (const ModelPart& part : model.parts)
        for_each_edge(part, [&](const EdgeKey& edge, int way) { balance[edge] += way; });
    std::vector<bool> open;
    for (const ModelPart& part : model.parts) {
        bool has_border = false;
        for_each_edge(part, [&](const EdgeKey& edge, int) { has_border = has_border || balance[edge] != 0; });
        open.push_back(has_border);
    }
    return open;
}

Mesh both_sides(const Mesh& mesh) {
    Mesh doubled = mesh;
    const auto count = static_cast<std::uint32_t>(mesh.positions.size());
    doubled.positions.insert(doubled.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (const glm::vec3& n : mesh.normals) doubled.normals.push_back(-n);
    if (!mesh.uvs.empty()) doubled.uvs.insert(doubled.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    if (!mesh.colours.empty()) doubled.colours.insert(doubled.colours.end(), mesh.colours.begin(), mesh.colours.end());
    if (!mesh.alphas.empty()) doubled.alphas.insert(doubled.alphas.end(), mesh.alphas.begin(), mesh.alphas.end());
    // The back's whole tangent frame turns round (w too, as n x t does not), as glTF's double-sided back faces.
    for (const glm::vec4& t : mesh.tangents) doubled.tangents.push_back(-t);
    for (const Facet& facet : mesh.facets) {
        const auto& c = facet.corners;
        doubled.facets.push_back({{c[0] + count, c[2] + count, c[1] + count}, -facet.normal});
    }
    doubled.convex = false;  // one side can now hide the other
    return doubled;
}

}  // namespace raster
