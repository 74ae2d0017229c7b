// The mesh builder's vertex lookup: every vertex keeps the id it was first given, in a position's
// chain and past it, where a fan's centre moves its vertices to a table (src/io/vertex_ids.hpp).
#include "io/vertex_ids.hpp"
#include "io/model_builder.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>
#include <gtest/gtest.h>

using raster::detail::VertexIds;
using raster::detail::VertexKey;

namespace {

// The k-th vertex at `position`: one normal bit pattern each, as a fan's facets give its centre.
VertexKey key_at(std::uint32_t position, std::uint32_t k) {
    constexpr std::uint32_t kNone = raster::detail::kNoIndex;
    return {position, k, 7, 9, kNone, kNone, kNone};
}

}  // namespace

TEST(VertexIds, EveryVertexKeepsItsFirstIdInAChainAndPastItsLength) {
    VertexIds ids(3);
    const std::uint32_t many = 4 * VertexIds::kLongestChain;  // well past the chain: the table holds them
    std::uint32_t next = 0;
    for (const int material : {0, 1}) {
        for (std::uint32_t k = 0; k < many; ++k) {
            const auto [id, added] = ids.find_or_add(material, key_at(1, k), next);
            EXPECT_EQ(id, next);
            EXPECT_TRUE(added) << material << ' ' << k;
            ++next;
        }
    }
    const auto [lone, lone_added] = ids.find_or_add(0, key_at(2, 0), next);  // another position: its own chain
    EXPECT_TRUE(lone_added);
    EXPECT_EQ(lone, next);
    for (const int material : {0, 1}) {
        for (std::uint32_t k = 0; k < many; ++k) {
            const auto [id, added] = ids.find_or_add(material, key_at(1, k), 99999);
            EXPECT_FALSE(added) << material << ' ' << k;
            EXPECT_EQ(id, static_cast<std::uint32_t>(material) * many + k);
        }
    }
    EXPECT_EQ(ids.find_or_add(0, key_at(2, 0), 99999).first, lone);
    EXPECT_TRUE(ids.find_or_add(0, key_at(0, 0), 5).second);  // nothing at position 0 yet
}

TEST(VertexIds, AFanOfThousandsOfFacetsKeepsAVertexForEachNormalAtItsCentre) {
    // Crease 0: every corner keeps its facet's normal, so the centre is a vertex per normal.
    raster::detail::PolygonSoup soup;
    const int facets = 20000;
    soup.positions.emplace_back(0.0F, 0.0F, 0.0F);
    for (int k = 0; k < facets; ++k) {
        const double angle = 2.0 * 3.141592653589793 * k / facets;
        soup.positions.emplace_back(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)),
                                    static_cast<float>(0.1 * std::sin(7.0 * angle)));
    }
    const auto corner = [](int i) { return raster::detail::SoupCorner{static_cast<std::uint32_t>(i)}; };
    for (int k = 0; k < facets; ++k)
        soup.triangles.push_back({{corner(0), corner(1 + (k + 1) % facets), corner(1 + k)}, 0});
    const auto meshes = raster::detail::meshes_by_material(soup, 0.0);
    ASSERT_EQ(meshes.size(), 1U);
    const raster::Mesh& mesh = meshes[0].second;
    ASSERT_EQ(mesh.facets.size(), static_cast<std::size_t>(facets));
    // One centre vertex for each distinct normal its facets give it (neighbours may round alike).
    std::set<std::uint32_t> centres;
    std::set<std::array<float, 3>> normals;
    for (const raster::Facet& facet : mesh.facets) {
        const std::uint32_t centre = facet.corners[0];
        EXPECT_EQ(mesh.positions[centre], glm::vec3(0.0F));
        EXPECT_EQ(mesh.normals[centre], facet.normal);
        centres.insert(centre);
        normals.insert({facet.normal.x, facet.normal.y, facet.normal.z});
    }
    EXPECT_EQ(centres.size(), normals.size());
    EXPECT_GT(centres.size(), 4 * VertexIds::kLongestChain);  // past the chain, into the table
}
