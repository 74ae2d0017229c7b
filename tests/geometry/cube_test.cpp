#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/cube.hpp>
#include <raster/rasterize/draw_cube.hpp>
#include <raster/scenes/scenes.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using raster::Cube;

namespace {

std::vector<std::size_t> faces_toward_camera(const Cube& cube) {
    return raster::faces_toward_camera(raster::OrthoCamera(800, 600), cube);
}

glm::vec3 centre_of(const Cube& cube, const raster::Face& face) {
    glm::vec3 sum(0.0F);
    for (const std::size_t corner : face.corners) sum += cube.corners()[corner];
    return sum / 4.0F;
}

void expect_near(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5F);
    EXPECT_NEAR(actual.y, expected.y, 1e-5F);
    EXPECT_NEAR(actual.z, expected.z, 1e-5F);
}

}  // namespace

TEST(Cube, UnitCubeHasEdgeOneCentredAtTheOrigin) {
    const Cube cube;
    for (const glm::vec3 corner : cube.corners()) {
        EXPECT_EQ(std::abs(corner.x), 0.5F);
        EXPECT_EQ(std::abs(corner.y), 0.5F);
        EXPECT_EQ(std::abs(corner.z), 0.5F);
    }
    glm::vec3 sum(0.0F);
    for (const glm::vec3 corner : cube.corners()) sum += corner;
    EXPECT_EQ(sum, glm::vec3(0.0F));
}

TEST(Cube, FaceNormalsAreOutwardUnitVectorsInSlotOrder) {
    const Cube cube;
    const std::array<glm::vec3, 6> expected{{{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}}};
    for (std::size_t slot = 0; slot < 6; ++slot) {
        const raster::Face& face = cube.faces()[slot];
        EXPECT_EQ(face.normal, expected[slot]) << "slot " << slot;
        expect_near(centre_of(cube, face), 0.5F * face.normal);
    }
}

TEST(Cube, FaceCornersRunClockwiseSeenFromOutside) {
    const Cube cube;
    for (const raster::Face& face : cube.faces()) {
        const glm::vec3 a = cube.corners()[face.corners[0]];
        const glm::vec3 b = cube.corners()[face.corners[1]];
        const glm::vec3 c = cube.corners()[face.corners[2]];
        // With +Y up and +X right, (b - a) x (c - b) points toward a viewer who sees a->b->c clockwise.
        expect_near(glm::normalize(glm::cross(b - a, c - b)), face.normal);
    }
}

TEST(Cube, LookingFromTheFrontShowsOnlyTheNearFace) {
    const Cube cube;
    const std::vector<std::size_t> visible = faces_toward_camera(cube);
    ASSERT_EQ(visible, std::vector<std::size_t>{raster::kNearFace});
    for (const std::size_t corner : cube.faces()[visible[0]].corners) {
        EXPECT_EQ(cube.corners()[corner].z, -0.5F);
    }
}

TEST(Cube, LookingFromBehindShowsOnlyTheFarFace) {
    const Cube turned = Cube().posed(glm::rotate(glm::mat4(1.0F), std::numbers::pi_v<float>, glm::vec3(0, 1, 0)));
    EXPECT_EQ(faces_toward_camera(turned), std::vector<std::size_t>{raster::kFarFace});
}

TEST(Cube, StillPoseShowsThreeFacesAndNineEdges) {
    const Cube cube = Cube().posed(raster::still_cube_pose());
    EXPECT_EQ(faces_toward_camera(cube),
              (std::vector<std::size_t>{raster::kNearFace, raster::kRightFace, raster::kBottomFace}));
    EXPECT_EQ(cube.edges_of(faces_toward_camera(cube)).size(), 9U);
}

TEST(Cube, EdgesAreListedOnceWithTheSmallerCornerFirst) {
    const Cube cube = Cube().posed(raster::still_cube_pose());
    for (const auto& edges : {cube.edges(), cube.edges_of(faces_toward_camera(cube))}) {
        for (std::size_t i = 0; i < edges.size(); ++i) {
            EXPECT_LT(edges[i].from, edges[i].to);
            EXPECT_EQ(std::count(edges.begin(), edges.end(), edges[i]), 1);
        }
    }
    EXPECT_EQ(cube.edges().size(), 12U);
}

TEST(Cube, PosedNormalsStayPerpendicularToFacesUnderNonUniformScale) {
    glm::mat4 model = glm::rotate(glm::mat4(1.0F), 0.7F, glm::vec3(0.3F, 1.0F, 0.2F));
    model = glm::scale(model, glm::vec3(3.0F, 0.5F, 1.5F));
    model = glm::rotate(model, -0.4F, glm::vec3(1.0F, 0.0F, 0.0F));
    const Cube cube = Cube().posed(model);
    for (const raster::Face& face : cube.faces()) {
        const glm::vec3 a = cube.corners()[face.corners[0]];
        const glm::vec3 b = cube.corners()[face.corners[1]];
        const glm::vec3 c = cube.corners()[face.corners[2]];
        EXPECT_NEAR(glm::length(face.normal), 1.0F, 1e-5F);
        expect_near(face.normal, glm::normalize(glm::cross(b - a, c - b)));
    }
}

TEST(Cube, EveryTumbleFrameShowsBetweenOneAndThreeFaces) {
    for (int frame = 0; frame < raster::kAnimationFrameCount; ++frame) {
        const auto visible =
            faces_toward_camera(Cube().posed(raster::tumble_pose(frame, raster::kAnimationFrameCount)));
        EXPECT_GE(visible.size(), 1U) << "frame " << frame;
        EXPECT_LE(visible.size(), 3U) << "frame " << frame;
    }
}
