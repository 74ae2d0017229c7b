#include <raster/geometry/mesh.hpp>
#include <raster/geometry/shapes.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace {

// The normal a posed facet should have, recomputed from its posed corners.
glm::vec3 normal_from_corners(const raster::Mesh& mesh, const raster::Facet& facet) {
    return raster::facet_normal(mesh.positions[facet.corners[0]], mesh.positions[facet.corners[1]],
                                mesh.positions[facet.corners[2]]);
}

}  // namespace

// The 0.0.14 bug: normals moved by the model matrix itself tilt under non-uniform scale.
TEST(PosedMesh, NormalsStayPerpendicularUnderNonUniformScale) {
    const raster::Mesh triangle{{{0, 0, 0}, {1, 1, 0}, {1, 0, 1}},
                                {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}},
                                {{{0, 1, 2}, raster::facet_normal({0, 0, 0}, {1, 1, 0}, {1, 0, 1})}}};
    const glm::mat4 squash = glm::scale(glm::mat4(1.0F), glm::vec3(1.0F, 0.5F, 1.0F));
    const raster::Mesh posed = raster::posed(triangle, squash);
    const glm::vec3 expected = normal_from_corners(posed, posed.facets[0]);
    EXPECT_NEAR(glm::distance(posed.facets[0].normal, expected), 0.0F, 1e-6F);
    // What the bug computed: the linear part applied to the normal, renormalised.
    const glm::vec3 buggy = glm::normalize(glm::vec3(squash * glm::vec4(triangle.facets[0].normal, 0.0F)));
    EXPECT_GT(glm::distance(buggy, expected), 0.1F) << "the test would not see the bug";
}

TEST(PosedMesh, SphereVertexNormalsFollowTheSquashedSurface) {
    const glm::mat4 squash = glm::scale(glm::mat4(1.0F), glm::vec3(0.7F, 0.15F, 0.7F));
    const raster::Mesh ellipsoid = raster::posed(raster::sphere(3), squash);
    for (std::size_t i = 0; i < ellipsoid.positions.size(); ++i) {
        // Gradient of x^2/a^2 + y^2/b^2 + z^2/c^2 at the point.
        const glm::vec3 p = ellipsoid.positions[i];
        const glm::vec3 gradient = glm::normalize(p / glm::vec3(0.49F, 0.0225F, 0.49F));
        EXPECT_NEAR(glm::distance(ellipsoid.normals[i], gradient), 0.0F, 1e-4F) << i;
    }
}

TEST(PosedMesh, MirroringKeepsFacetsClockwiseFromOutside) {
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0F), glm::vec3(-1.0F, 2.0F, 1.0F));
    const raster::Mesh cube = raster::posed(raster::cube_mesh(), mirror);
    for (const raster::Facet& facet : cube.facets) {
        EXPECT_NEAR(glm::distance(facet.normal, normal_from_corners(cube, facet)), 0.0F, 1e-6F);
        const glm::vec3 centre = (cube.positions[facet.corners[0]] + cube.positions[facet.corners[2]]) / 2.0F;
        EXPECT_GT(glm::dot(facet.normal, centre), 0.0F) << "outward";
    }
}

TEST(PosedMesh, SingularAndNonFiniteModelsGiveZeroNormalsNotNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const glm::mat4& model : {glm::scale(glm::mat4(1.0F), glm::vec3(1.0F, 0.0F, 1.0F)), glm::mat4(nan),
                                   glm::mat4(std::numeric_limits<float>::infinity())}) {
        const raster::Mesh posed = raster::posed(raster::sphere(1), model);
        for (const glm::vec3& n : posed.normals) EXPECT_EQ(n, glm::vec3(0.0F));
        for (const raster::Facet& facet : posed.facets) EXPECT_EQ(facet.normal, glm::vec3(0.0F));
    }
}

TEST(PosedMesh, PartsLeftOutAreZeroAndTheRestMatchAFullPose) {
    const raster::Mesh sphere = raster::sphere(2);
    const glm::mat4 model =
        glm::rotate(glm::scale(glm::mat4(1.0F), glm::vec3(2.0F, 1.0F, 0.5F)), 0.7F, glm::vec3(1, 2, 3));
    const raster::Mesh full = raster::posed(sphere, model);
    const raster::Mesh smooth = raster::posed(sphere, model, {.vertex_normals = true, .facet_normals = false});
    const raster::Mesh flat = raster::posed(sphere, model, {.vertex_normals = false, .facet_normals = true});
    EXPECT_EQ(smooth.positions, full.positions);
    EXPECT_EQ(smooth.normals, full.normals);
    EXPECT_EQ(flat.positions, full.positions);
    ASSERT_EQ(flat.normals.size(), full.normals.size());
    for (std::size_t i = 0; i < full.facets.size(); ++i) {
        EXPECT_EQ(flat.facets[i].corners, full.facets[i].corners);
        EXPECT_EQ(flat.facets[i].normal, full.facets[i].normal);
        EXPECT_EQ(smooth.facets[i].normal, glm::vec3(0.0F));
    }
    for (const glm::vec3& normal : flat.normals) EXPECT_EQ(normal, glm::vec3(0.0F));
}

TEST(FacetNormal, DegenerateCornersHaveNoNormal) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(raster::facet_normal({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), glm::vec3(0.0F));
    EXPECT_EQ(raster::facet_normal({1, 2, 3}, {1, 2, 3}, {1, 2, 3}), glm::vec3(0.0F));
    EXPECT_EQ(raster::facet_normal({nan, 0, 0}, {0, 1, 0}, {1, 0, 0}), glm::vec3(0.0F));
    EXPECT_EQ(raster::unit_or_zero({0, 0, 0}), glm::vec3(0.0F));
    EXPECT_EQ(raster::unit_or_zero({0, 3, 4}), glm::vec3(0.0F, 0.6F, 0.8F));
}

// Alphas are carried as colours are: unmoved by posing, appended after the whole's, and a part
// with them never joins one without (doc/conventions.md#vertex-alpha).
TEST(PosedMesh, VertexAlphasArePosedAndAppendedAsColoursAre) {
    raster::Mesh part = raster::cube_mesh();
    part.alphas.assign(part.positions.size(), 0.5F);
    const glm::mat4 moved = glm::translate(glm::mat4(1.0F), glm::vec3(2, 0, 0));
    EXPECT_EQ(raster::posed(part, moved).alphas, part.alphas);
    raster::Mesh whole;
    raster::append_posed(whole, part, moved);
    raster::append_posed(whole, part, glm::mat4(1.0F));
    EXPECT_EQ(whole.alphas.size(), 2 * part.positions.size());
    raster::Mesh opaque = raster::cube_mesh();
    EXPECT_THROW(raster::append_posed(whole, opaque, glm::mat4(1.0F)), std::invalid_argument);
}
