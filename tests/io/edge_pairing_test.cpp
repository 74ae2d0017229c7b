// Open parts are found by sorting packed edge keys (issue 31): the same parts as counting every
// edge's uses in a map of exact positions, and the sort the same as std::sort.
#include <raster/io/model.hpp>

#include "io/radix_sort.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <random>
#include <vector>

namespace {

// The reference: each edge's uses one way minus the other, by the positions' bits, as 0.1.38 counted them.
std::vector<bool> open_parts_by_counting(const raster::Model& model) {
    using Point = std::array<std::uint32_t, 3>;
    const auto bits = [](glm::vec3 p) {
        Point key{};
        std::memcpy(key.data(), &p.x, 12);
        return key;
    };
    std::map<std::pair<Point, Point>, long> balance;
    const auto each_edge = [&](const raster::ModelPart& part, const auto& visit) {
        for (const raster::Facet& facet : part.mesh.facets) {
            for (std::size_t k = 0; k < 3; ++k) {
                const Point a = bits(part.mesh.positions[facet.corners[k]]);
                const Point b = bits(part.mesh.positions[facet.corners[(k + 1) % 3]]);
                visit(a < b ? std::pair{a, b} : std::pair{b, a}, a < b ? 1 : -1);
            }
        }
    };
    for (const raster::ModelPart& part : model.parts)
        each_edge(part, [&](const auto& edge, int way) { balance[edge] += way; });
    std::vector<bool> open;
    for (const raster::ModelPart& part : model.parts) {
        bool border = false;
        each_edge(part, [&](const auto& edge, int) { border = border || balance[edge] != 0; });
        open.push_back(border);
    }
    return open;
}

// A model of `parts` parts of random facets over a few positions, some shared between parts,
// with signed zeros, repeated positions and facets with two corners at one position.
raster::Model random_model(std::mt19937& random, int parts) {
    const std::vector<glm::vec3> places = {{0, 0, 0}, {-0.0F, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    raster::Model model;
    for (int p = 0; p < parts; ++p) {
        raster::Mesh& mesh = model.parts.emplace_back().mesh;
        for (int v = 0; v < 8; ++v) mesh.positions.push_back(places[random() % places.size()]);
        const auto corner = [&] { return static_cast<std::uint32_t>(random() % mesh.positions.size()); };
        for (auto f = random() % 6; f > 0; --f) mesh.facets.push_back({{corner(), corner(), corner()}, {}});
        if (random() % 4 == 0) {  // a closed tetrahedron, alone or seen by other parts
            const std::uint32_t base = static_cast<std::uint32_t>(mesh.positions.size());
            for (int v = 2; v < 6; ++v) mesh.positions.push_back(places[static_cast<std::size_t>(v)]);
            for (const auto& f : {std::array<std::uint32_t, 3>{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}})
                mesh.facets.push_back({{base + f[0], base + f[1], base + f[2]}, {}});
        }
    }
    return model;
}

}  // namespace

TEST(EdgePairing, SortedEdgeKeysFindTheOpenPartsThatCountingEveryEdgeFinds) {
    std::mt19937 random(30);
    int open = 0, closed = 0;
    for (int round = 0; round < 2000; ++round) {
        const raster::Model model = random_model(random, 1 + round % 4);
        const std::vector<bool> expected = open_parts_by_counting(model);
        ASSERT_EQ(raster::open_parts(model), expected) << "round " << round;
        for (std::size_t i = 0; i < expected.size(); ++i) (expected[i] ? open : closed) += 1;
    }
    EXPECT_GT(open, 100);  // both answers were asked for many times
    EXPECT_GT(closed, 100);
}

TEST(EdgePairing, RadixSortSortsAsStdSortWhateverBytesTheKeysShare) {
    std::mt19937_64 random(31);
    for (const std::uint64_t mask : {~std::uint64_t{0}, std::uint64_t{0xFFFF'0000'00FF}, std::uint64_t{0}}) {
        for (const std::size_t size : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{100'000}}) {
            std::vector<std::uint64_t> keys(size);
            for (std::uint64_t& key : keys) key = random() & mask;
            std::vector<std::uint64_t> expected = keys;
            std::sort(expected.begin(), expected.end());
            raster::detail::radix_sort(keys);
            EXPECT_EQ(keys, expected) << size << " keys under mask " << mask;
        }
    }
}
