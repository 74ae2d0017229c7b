#include <raster/io/model.hpp>

#include "io/radix_sort.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace raster {

namespace {

// A position by its bits: parts split a vertex by normal and texture coordinate, but a seam
// between them is still closed where the positions are the same.
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

// One number for each position of every part with facets, the same for the same bits: an
// open-addressed table, linear in the positions, with no node allocated for each.
std::vector<std::vector<std::uint32_t>> position_ids(const Model& model) {
    std::size_t total = 0;
    for (const ModelPart& part : model.parts) total += part.mesh.facets.empty() ? 0 : part.mesh.positions.size();
    std::size_t capacity = 16;
    while (capacity < 2 * total) capacity *= 2;
    std::vector<std::uint32_t> table(capacity, 0);  // an id plus one; 0 for an empty slot
    std::vector<PointKey> known;
    std::vector<std::vector<std::uint32_t>> ids(model.parts.size());
    for (std::size_t i = 0; i < model.parts.size(); ++i) {
        const Mesh& mesh = model.parts[i].mesh;
        if (mesh.facets.empty()) continue;
        ids[i].reserve(mesh.positions.size());
        for (const glm::vec3& p : mesh.positions) {
            const PointKey key = key_of(p);
            std::uint64_t h =
                (key.x * 0x9E3779B97F4A7C15ULL) ^ (key.y * 0xC2B2AE3D27D4EB4FULL) ^ (key.z * 0x165667B19E3779F9ULL);
            h ^= h >> 29;
            std::size_t slot = static_cast<std::size_t>(h) & (capacity - 1);
            while (table[slot] != 0 && !(known[table[slot] - 1] == key)) slot = (slot + 1) & (capacity - 1);
            if (table[slot] == 0) {
                known.push_back(key);
                table[slot] = static_cast<std::uint32_t>(known.size());
            }
            ids[i].push_back(table[slot] - 1);
        }
    }
    return ids;
}

// An edge as one number, its ends' ids in order, so both ways round share it.
std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

// Calls `visit(a, b)` with the position ids of each edge of each facet of the part, in winding order.
template <typename Visit>
void for_each_edge(const Mesh& mesh, const std::vector<std::uint32_t>& ids, const Visit& visit) {
    for (const Facet& facet : mesh.facets) {
        for (std::size_t k = 0; k < 3; ++k) visit(ids[facet.corners[k]], ids[facet.corners[(k + 1) % 3]]);
    }
}

// The fields both_sides knows to double: one added to Mesh fails the assertion below until it is.
struct DoubledFields {
    std::vector<glm::vec3> positions, normals;
    std::vector<Facet> facets;
    Surface surface;
    bool convex;
    std::vector<glm::vec2> uvs;
    std::vector<LinearRgb> colours;
    std::vector<float> alphas;
    std::vector<std::uint32_t> points;
    std::vector<std::array<std::uint32_t, 2>> segments;
    std::vector<glm::vec4> tangents;
};
static_assert(sizeof(DoubledFields) == sizeof(Mesh), "both_sides must double every field of Mesh");

}  // namespace

std::vector<bool> open_parts(const Model& model) {
    // Each edge's uses one way and the other, over the whole model, as sorted keys: a closed,
    // consistently wound surface uses every edge as often each way, however its parts divide it.
    // An edge from a position to itself counts as used backwards only, so it never pairs.
    const std::vector<std::vector<std::uint32_t>> ids = position_ids(model);
    std::vector<std::uint64_t> forwards, backwards;
    std::size_t edges = 0;
    for (const ModelPart& part : model.parts) edges += 3 * part.mesh.facets.size();
    forwards.reserve(edges);
    backwards.reserve(edges);
    for (std::size_t i = 0; i < model.parts.size(); ++i) {
        for_each_edge(model.parts[i].mesh, ids[i], [&](std::uint32_t a, std::uint32_t b) {
            (a < b ? forwards : backwards).push_back(edge_key(a, b));
        });
    }
    detail::radix_sort(forwards);
    detail::radix_sort(backwards);
    std::vector<std::uint64_t> unpaired;  // sorted, as the walk meets them
    for (std::size_t f = 0, b = 0; f < forwards.size() || b < backwards.size();) {
        const std::uint64_t key =
            b == backwards.size() || (f < forwards.size() && forwards[f] < backwards[b]) ? forwards[f] : backwards[b];
        std::size_t way = 0, other = 0;
        for (; f < forwards.size() && forwards[f] == key; ++f) ++way;
        for (; b < backwards.size() && backwards[b] == key; ++b) ++other;
        if (way != other) unpaired.push_back(key);
    }
    std::vector<bool> open(model.parts.size(), false);
    if (unpaired.empty()) return open;
    for (std::size_t i = 0; i < model.parts.size(); ++i) {
        bool has_border = false;
        for_each_edge(model.parts[i].mesh, ids[i], [&](std::uint32_t a, std::uint32_t b) {
            has_border = has_border || std::binary_search(unpaired.begin(), unpaired.end(), edge_key(a, b));
        });
        open[i] = has_border;
    }
    return open;
}

Mesh both_sides(const Mesh& mesh) {
    // Every array sized once for both copies: a large mesh is neither copied twice nor moved as it grows.
    const auto twice = [](const auto& items) {
        std::remove_cvref_t<decltype(items)> doubled;
        doubled.reserve(2 * items.size());
        doubled.insert(doubled.end(), items.begin(), items.end());
        return doubled;
    };
    Mesh doubled;
    doubled.surface = mesh.surface;
    doubled.positions = twice(mesh.positions);
    doubled.normals = twice(mesh.normals);
    doubled.uvs = twice(mesh.uvs);
    doubled.colours = twice(mesh.colours);
    doubled.alphas = twice(mesh.alphas);
    doubled.tangents = twice(mesh.tangents);
    doubled.facets = twice(mesh.facets);
    doubled.points = mesh.points;
    doubled.segments = mesh.segments;
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
