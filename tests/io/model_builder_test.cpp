// Meshes built from a soup on several threads are the meshes built on one (src/io/model_builder.hpp).
#include "io/model_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

namespace {

// Every byte of a mesh's positions, normals and facets.
template <typename Values>
std::string bytes_of(const Values& values) {
    std::string bytes(values.size() * sizeof values[0], '\0');
    if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
    return bytes;
}

}  // namespace

TEST(MeshBuilder, AnyThreadCountBuildsTheSameMeshes) {
    // A wavy height field of 280,000 triangles in two materials, with no normals: more than the
    // blocks one round of corner normals holds, so the rounds and the threads both split it.
    constexpr std::uint32_t kWide = 401, kDeep = 351;
    raster::detail::PolygonSoup soup;
    for (std::uint32_t y = 0; y < kDeep; ++y) {
        for (std::uint32_t x = 0; x < kWide; ++x) {
            soup.positions.emplace_back(static_cast<float>(x),
                                        static_cast<float>(std::sin(x * 0.3) * std::cos(y * 0.2)),
                                        static_cast<float>(y));
        }
    }
    for (std::uint32_t y = 0; y + 1 < kDeep; ++y) {
        for (std::uint32_t x = 0; x + 1 < kWide; ++x) {
            const std::uint32_t a = y * kWide + x;
            const int material = (x / 50 + y / 50) % 2;
            soup.triangles.push_back({{{{a}, {a + kWide}, {a + 1}}}, material});
            soup.triangles.push_back({{{{a + 1}, {a + kWide}, {a + kWide + 1}}}, material});
        }
    }
    const auto one = raster::detail::meshes_by_material(soup, 60.0, 1);
    const auto three = raster::detail::meshes_by_material(soup, 60.0, 3);
    ASSERT_EQ(one.size(), 2U);
    ASSERT_EQ(three.size(), one.size());
    // Every vertex takes the area-weighted mean of the facets around its position (all within 60 degrees).
    std::vector<glm::dvec3> around(soup.positions.size(), glm::dvec3(0.0));
    for (const raster::detail::SoupTriangle& triangle : soup.triangles) {
        const auto at = [&](int k) { return glm::dvec3(soup.positions[triangle.corners[k].position]); };
        const glm::dvec3 weighted = glm::cross(at(1) - at(0), at(2) - at(1));
        for (const auto& corner : triangle.corners) around[corner.position] += weighted;
    }
    std::size_t wrong = 0;
    for (const auto& [material, mesh] : one) {
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const auto x = static_cast<std::size_t>(mesh.positions[v].x),
                       y = static_cast<std::size_t>(mesh.positions[v].z);
            const glm::dvec3 expected = glm::normalize(around[y * kWide + x]);
            wrong += glm::length(glm::dvec3(mesh.normals[v]) - expected) > 1e-5 ? 1 : 0;
        }
    }
    EXPECT_EQ(wrong, 0U);
    for (std::size_t m = 0; m < one.size(); ++m) {
        EXPECT_EQ(three[m].first, one[m].first);
        EXPECT_GT(one[m].second.facets.size(), 100'000U);
        EXPECT_TRUE(bytes_of(three[m].second.positions) == bytes_of(one[m].second.positions));
        EXPECT_TRUE(bytes_of(three[m].second.normals) == bytes_of(one[m].second.normals));
        EXPECT_TRUE(bytes_of(three[m].second.facets) == bytes_of(one[m].second.facets));
    }
}
