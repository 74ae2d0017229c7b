// Tangents made from texture coordinates for normal maps (doc/conventions.md#normal-maps): along u,
// with the handedness that puts the bitangent along v, averaged by corner angle, and finite
// whatever the coordinates; and moved by posing like directions.
#include <raster/geometry/mesh.hpp>
#include <raster/geometry/shapes.hpp>
#include <raster/geometry/tangents.hpp>

#include <cmath>
#include <vector>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace {

// A square in the z = 0 plane facing -z (toward a camera on -z), corners clockwise seen from
// there, with texture coordinates `uvs` at its corners (-1, 1), (1, 1), (1, -1), (-1, -1).
raster::Mesh square(std::vector<glm::vec2> uvs) {
    raster::Mesh mesh;
    mesh.positions = {{-1, 1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
    mesh.normals.assign(4, glm::vec3(0, 0, -1));
    mesh.uvs = std::move(uvs);
    mesh.facets = {{{0, 1, 2}, {0, 0, -1}}, {{0, 2, 3}, {0, 0, -1}}};
    return mesh;
}

// The bitangent a tangent stands for: w (n x t).
glm::vec3 bitangent(glm::vec3 normal, glm::vec4 tangent) { return glm::cross(normal, glm::vec3(tangent)) * tangent.w; }

void expect_near(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(glm::distance(actual, expected), 0.0F, 1e-5F) << actual.x << ' ' << actual.y << ' ' << actual.z;
}

}  // namespace

TEST(Tangents, FollowTheUDirectionOnAFlatQuad) {
    const raster::Mesh upright = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});  // u along +x, v along +y
    const std::vector<glm::vec4> tangents = raster::tangents_from_uvs(upright);
    ASSERT_EQ(tangents.size(), 4U);
    for (std::size_t i = 0; i < 4; ++i) {
        expect_near(glm::vec3(tangents[i]), {1, 0, 0});
        expect_near(bitangent(upright.normals[i], tangents[i]), {0, 1, 0});
    }
    // The image turned a quarter: u runs down the square, v to the right.
    const raster::Mesh turned = square({{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    for (const glm::vec4& t : raster::tangents_from_uvs(turned)) {
        expect_near(glm::vec3(t), {0, -1, 0});
        expect_near(bitangent({0, 0, -1}, t), {1, 0, 0});
    }
    // Stretched texture coordinates change the lengths of dP/du and dP/dv, not the directions.
    const raster::Mesh stretched = square({{0, 4}, {0.5F, 4}, {0.5F, 0}, {0, 0}});
    for (const glm::vec4& t : raster::tangents_from_uvs(stretched)) expect_near(glm::vec3(t), {1, 0, 0});
    EXPECT_TRUE(raster::tangents_from_uvs(square({})).empty());
}

// A mirrored texture (u running right to left) keeps its bitangent along v: w turns instead.
TEST(Tangents, HandednessFlipsWithMirroredUvs) {
    const raster::Mesh upright = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const raster::Mesh mirrored = square({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
    const std::vector<glm::vec4> ahead = raster::tangents_from_uvs(upright);
    const std::vector<glm::vec4> back = raster::tangents_from_uvs(mirrored);
    ASSERT_EQ(back.size(), 4U);
    for (std::size_t i = 0; i < 4; ++i) {
        expect_near(glm::vec3(back[i]), {-1, 0, 0});
        EXPECT_EQ(back[i].w, -ahead[i].w);
        expect_near(bitangent(mirrored.normals[i], back[i]), {0, 1, 0});
    }
}

// A mesh drawn by its facets' normals (no vertex normals) takes its handedness from them.
TEST(Tangents, WithoutVertexNormalsTheFacetsDecideTheHandedness) {
    raster::Mesh upright = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    raster::Mesh mirrored = square({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
    upright.normals.clear(), mirrored.normals.clear();
    const std::vector<glm::vec4> ahead = raster::tangents_from_uvs(upright);
    const std::vector<glm::vec4> back = raster::tangents_from_uvs(mirrored);
    ASSERT_EQ(back.size(), 4U);
    for (std::size_t i = 0; i < 4; ++i) {
        expect_near(bitangent({0, 0, -1}, ahead[i]), {0, 1, 0});
        expect_near(bitangent({0, 0, -1}, back[i]), {0, 1, 0});
        EXPECT_EQ(back[i].w, -ahead[i].w);
    }
}

// Texture coordinates all equal, along a line, or not finite, and normals of no length: every
// tangent is still a unit vector perpendicular to its normal, w is ±1, nothing is NaN.
TEST(Tangents, DegenerateUvsStayFinite) {
    const float nan = std::nanf("");
    std::vector<raster::Mesh> meshes{
        square({{0.5F, 0.5F}, {0.5F, 0.5F}, {0.5F, 0.5F}, {0.5F, 0.5F}}), square({{0, 0}, {1, 1}, {2, 2}, {3, 3}}),
        square({{nan, 0}, {1, nan}, {1, 0}, {0, 0}}), square({{0, 1}, {1, 1}, {1, 0}, {0, 0}})};
    meshes.back().normals.assign(4, glm::vec3(0.0F));
    raster::Mesh tilted = square({{0, 0}, {0, 0}, {0, 0}, {0, 0}});
    tilted.normals.assign(4, glm::normalize(glm::vec3(1, 0.2F, -0.1F)));  // perpendicular to nothing easy
    meshes.push_back(tilted);
    for (const raster::Mesh& mesh : meshes) {
        const std::vector<glm::vec4> tangents = raster::tangents_from_uvs(mesh);
        ASSERT_EQ(tangents.size(), 4U);
        for (std::size_t i = 0; i < 4; ++i) {
            const glm::vec4& t = tangents[i];
            ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w));
            EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0F, 1e-5F);
            EXPECT_NEAR(glm::dot(glm::vec3(t), mesh.normals[i]), 0.0F, 1e-5F);
            EXPECT_EQ(std::abs(t.w), 1.0F);
        }
    }
}

// On a sphere mapped by longitude and latitude every tangent is perpendicular to its normal and
// runs round the axis, as u does.
TEST(Tangents, RunAlongUAndPerpendicularToTheNormalOnACurvedSurface) {
    raster::Mesh globe = raster::sphere(3);
    for (const glm::vec3& p : globe.positions) globe.uvs.emplace_back(std::atan2(p.z, p.x), p.y);
    const std::vector<glm::vec4> tangents = raster::tangents_from_uvs(globe);
    ASSERT_EQ(tangents.size(), globe.positions.size());
    std::size_t checked = 0;
    for (std::size_t i = 0; i < tangents.size(); ++i) {
        const glm::vec3 t(tangents[i]);
        EXPECT_NEAR(glm::dot(t, globe.normals[i]), 0.0F, 1e-5F);
        const glm::vec3 p = globe.positions[i];
        if (std::abs(p.y) > 0.8F || (p.x < 0.0F && std::abs(p.z) < 0.3F)) continue;  // the poles and the seam at -x
        const glm::vec3 round = glm::normalize(glm::vec3(-p.z, 0.0F, p.x));          // where atan2(z, x) grows
        EXPECT_GT(glm::dot(t, round), 0.9F) << i;
        ++checked;
    }
    EXPECT_GT(checked, 10U);
}

// Tangents are directions in the surface: a non-uniform scale keeps them along the scaled u, and a
// mirror turns their handedness so that w (n x t) still runs along v.
TEST(PosedMesh, TangentsTurnWithTheModelAndAMirrorTurnsTheirHandedness) {
    raster::Mesh mesh = square({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    mesh.tangents = raster::tangents_from_uvs(mesh);
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0F), 0.5F, glm::vec3(0, 0, 1));
    const raster::Mesh turned = raster::posed(mesh, glm::scale(turn, glm::vec3(3.0F, 1.0F, 1.0F)));
    ASSERT_EQ(turned.tangents.size(), 4U);
    expect_near(glm::vec3(turned.tangents[0]), {std::cos(0.5F), std::sin(0.5F), 0});
    EXPECT_EQ(turned.tangents[0].w, mesh.tangents[0].w);
    const raster::Mesh mirrored = raster::posed(mesh, glm::scale(glm::mat4(1.0F), glm::vec3(-1.0F, 1.0F, 1.0F)));
    for (std::size_t i = 0; i < 4; ++i) {
        expect_near(glm::vec3(mirrored.tangents[i]), {-1, 0, 0});  // u still grows from corner 0 to 1
        EXPECT_EQ(mirrored.tangents[i].w, -mesh.tangents[i].w);
        expect_near(bitangent(mirrored.normals[i], mirrored.tangents[i]), {0, 1, 0});
    }
    const std::vector<glm::vec4> again = raster::tangents_from_uvs(mirrored);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(again[i].w, mirrored.tangents[i].w);
}
