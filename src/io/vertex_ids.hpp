#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

// The vertices a mesh builder has made, found by everything that tells one from another: each
// soup position heads a short chain of the vertices made at it (a corner's neighbours in the file
// are near in memory, where a hash would scatter them), and each vertex keeps the id it was
// given when first met, so a mesh's vertex order is the order its corners came in. A position
// with many vertices (a fan's centre, each corner its facet's normal) moves them to a hash table.
namespace raster::detail {

struct VertexKey {
    std::uint32_t position;  // into the soup's positions: every one below the count VertexIds was made for
    std::uint32_t normal_x, normal_y, normal_z;  // the normal's bits
    std::uint32_t uv, colour, tangent;
    friend bool operator==(const VertexKey&, const VertexKey&) = default;
};

class VertexIds {
public:
    explicit VertexIds(std::size_t positions) : heads_(positions, 0) {}

    // The id `key` was given in `material`'s mesh when first met, or `id` if it is new now; and whether it is.
    std::pair<std::uint32_t, bool> find_or_add(int material, const VertexKey& key, std::uint32_t id);

    // Vertices a position's chain holds before they move to the table: a chain is walked whole
    // for every new vertex, so a longer one would cost the square of a fan's facets.
    static constexpr std::size_t kLongestChain = 32;

private:
    struct Made {
        VertexKey key;
        int material;
        std::uint32_t id;
        std::uint32_t next;  // the next vertex at the same position, an index into made_ plus one; 0 ends
    };
    struct Spilled {
        VertexKey key;
        int material;
        friend bool operator==(const Spilled&, const Spilled&) = default;
    };
    struct SpilledHash {
        std::size_t operator()(const Spilled& s) const noexcept;
    };
    static constexpr std::uint32_t kInTable = 0xFFFFFFFFU;  // a head whose vertices are in spilled_

    std::vector<std::uint32_t> heads_;  // per position: its latest vertex, an index into made_ plus one
    std::vector<Made> made_;
    std::unordered_map<Spilled, std::uint32_t, SpilledHash> spilled_;
};

}  // namespace raster::detail
