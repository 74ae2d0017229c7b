#include <raster/geometry/shapes.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using raster::Mesh;

namespace {

// Every edge of a closed surface is shared by exactly two facets, walked once in each direction.
bool is_closed_and_consistently_wound(const Mesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const raster::Facet& facet : mesh.facets) {
        for (std::size_t k = 0; k < 3; ++k) ++directed[{facet.corners[k], facet.corners[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        if (count != 1 || directed.count({edge.second, edge.first}) != 1) return false;
    }
    return true;
}

glm::vec3 origin(glm::vec3) { return {0, 0, 0}; }

// Facet normals agree with the corners' clockwise-from-outside order and point away from the
// inside point nearest the facet.
void expect_outward_clockwise_facets(const Mesh& mesh, glm::vec3 (*inside_near)(glm::vec3) = origin) {
    for (const raster::Facet& facet : mesh.facets) {
        const glm::vec3 a = mesh.positions[facet.corners[0]], b = mesh.positions[facet.corners[1]],
                        c = mesh.positions[facet.corners[2]];
        const glm::vec3 inside = inside_near(a);
        EXPECT_NEAR(glm::length(facet.normal), 1.0F, 1e-5F);
        EXPECT_GT(glm::dot(glm::cross(b - a, c - b), facet.normal), 0.0F);
        EXPECT_GT(glm::dot((a + b + c) / 3.0F - inside, facet.normal), 0.0F);
    }
}

}  // namespace

TEST(Shapes, CubeIsTwelveFacetsOverEightCornersClosedAndOutward) {
    const Mesh cube = raster::cube_mesh();
    EXPECT_EQ(cube.positions.size(), 8U);
    EXPECT_EQ(cube.facets.size(), 12U);
    EXPECT_TRUE(cube.convex);
    EXPECT_EQ(cube.surface, raster::Surface::faceted);
    EXPECT_TRUE(is_closed_and_consistently_wound(cube));
    expect_outward_clockwise_facets(cube);
}

TEST(Shapes, DodecahedronHasTwentyCornersThirtySixFacetsAndReachesHalfAUnit) {
    const Mesh dodecahedron = raster::dodecahedron();
    EXPECT_EQ(dodecahedron.positions.size(), 20U);
    EXPECT_EQ(dodecahedron.facets.size(), 36U);
    EXPECT_TRUE(is_closed_and_consistently_wound(dodecahedron));
    expect_outward_clockwise_facets(dodecahedron);
    float largest = 0.0F;
    for (const glm::vec3& p : dodecahedron.positions)
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    EXPECT_NEAR(largest, 0.5F, 1e-6F);
    // Twelve regular pentagons: each fan of three facets shares one normal, edge 1/phi^2.
    std::set<std::tuple<int, int, int>> planes;
    for (const raster::Facet& facet : dodecahedron.facets) {
        planes.insert({std::lround(facet.normal.x * 1000), std::lround(facet.normal.y * 1000),
                       std::lround(facet.normal.z * 1000)});
    }
    EXPECT_EQ(planes.size(), 12U);
    const float phi = std::numbers::phi_v<float>;
    float shortest = 10.0F;
    for (std::size_t i = 0; i < 20; ++i) {
        for (std::size_t j = i + 1; j < 20; ++j)
            shortest = std::min(shortest, glm::distance(dodecahedron.positions[i], dodecahedron.positions[j]));
    }
    EXPECT_NEAR(shortest, 1.0F / (phi * phi), 1e-5F);
}

TEST(Shapes, SphereLevelsHaveTheDiaryCountsOnTheUnitSphere) {
    for (const auto& [level, facets, vertices] :
         {std::tuple{0, 8U, 6U}, {1, 32U, 18U}, {2, 128U, 66U}, {4, 2048U, 1026U}}) {
        const Mesh sphere = raster::sphere(level);
        EXPECT_EQ(sphere.facets.size(), facets) << "level " << level;
        EXPECT_EQ(sphere.positions.size(), vertices) << "level " << level;
        EXPECT_TRUE(is_closed_and_consistently_wound(sphere)) << "level " << level;
        expect_outward_clockwise_facets(sphere);
        for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
            EXPECT_NEAR(glm::length(sphere.positions[i]), 1.0F, 1e-6F);
            EXPECT_EQ(sphere.normals[i], sphere.positions[i]);
        }
    }
}

TEST(Shapes, TorusHasRingTimesTubeVerticesTwiceAsManyFacetsAndTrueNormals) {
    const Mesh torus = raster::torus(48, 32);
    EXPECT_EQ(torus.positions.size(), 1536U);
    EXPECT_EQ(torus.facets.size(), 3072U);
    EXPECT_FALSE(torus.convex);
    EXPECT_TRUE(is_closed_and_consistently_wound(torus));
    for (std::size_t i = 0; i < torus.positions.size(); ++i) {
        const glm::vec3 p = torus.positions[i];
        const glm::vec3 centre = raster::kTorusRingRadius * glm::normalize(glm::vec3(p.x, 0, p.z));
        EXPECT_NEAR(glm::distance(p, centre), raster::kTorusTubeRadius, 1e-6F);
        EXPECT_NEAR(glm::length(glm::normalize(p - centre) - torus.normals[i]), 0.0F, 1e-5F);
    }
    expect_outward_clockwise_facets(
        torus, [](glm::vec3 p) { return raster::kTorusRingRadius * glm::normalize(glm::vec3(p.x, 0, p.z)); });
}

TEST(Shapes, TessellationOutsideTheDocumentedLimitsIsAClearError) {
    EXPECT_THROW((void)raster::sphere(-1), std::invalid_argument);
    EXPECT_THROW((void)raster::sphere(raster::kMaxSphereLevel + 1), std::invalid_argument);
    EXPECT_THROW((void)raster::torus(2, 16), std::invalid_argument);
    EXPECT_THROW((void)raster::torus(16, 2), std::invalid_argument);
    EXPECT_THROW((void)raster::torus(1 << 11, (1 << 9) + 1), std::invalid_argument);
    EXPECT_THROW((void)raster::torus(1 << 30, 1 << 30), std::invalid_argument);  // would overflow int
    EXPECT_NO_THROW((void)raster::torus(1 << 11, 1 << 9));
    try {
        (void)raster::sphere(9);
        FAIL() << "level 9 built";
    } catch (const std::invalid_argument& error) {
        EXPECT_STREQ(error.what(), "sphere level must be 0..8, got 9");
    }
}
