// A cloud's automatic splat size from its box on screen, taken from an even sample of a cloud of
// millions (doc/conventions.md#points-and-lines).
#include <raster/camera/ortho_camera.hpp>
#include <raster/render/scene.hpp>

#include "render/draw_points_lines.hpp"

#include <cstdint>
#include <gtest/gtest.h>

namespace {

// A side x side grid of points over [-1, 1] squared, in rows, each point its own vertex.
raster::Mesh grid_cloud(int side) {
    raster::Mesh mesh;
    for (int row = 0; row < side; ++row) {
        for (int column = 0; column < side; ++column) {
            mesh.positions.emplace_back(-1.0F + 2.0F * static_cast<float>(column) / static_cast<float>(side - 1),
                                        -1.0F + 2.0F * static_cast<float>(row) / static_cast<float>(side - 1), 0.0F);
        }
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0F));
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) mesh.points.push_back(i);
    return mesh;
}

// The automatic size of the cloud's splats in a 1001 x 1001 view, 500 pixels a world unit.
double sized(const raster::Mesh& cloud) {
    const raster::OrthoCamera camera(1001, 1001);
    raster::detail::WorkerTeam team(2);
    return raster::detail::point_size(raster::detail::PointProjection<raster::OrthoCamera>(camera),
                                      raster::PointsAndLines{}, cloud, raster::detail::VertexPose(glm::mat4(1.0F)),
                                      team);
}

}  // namespace

TEST(PointSizing, ACloudOfMillionsIsSizedFromAnEvenSampleAsItsWholeWouldBe) {
    const raster::Mesh cloud = grid_cloud(1500);  // 2.25 million points: every other one is sampled
    ASSERT_GE(cloud.points.size(), 2 * raster::detail::kSizingPoints);
    const double whole = raster::automatic_point_size(1000.0 * 1000.0, cloud.points.size());
    ASSERT_GT(whole, raster::kMinPointSize);  // not clamped, so the sample's error would show
    EXPECT_NEAR(sized(cloud), whole, 1e-3 * whole);
}

TEST(PointSizing, ALonePointTheSampleSkipsDoesNotWidenTheBox) {
    // Where sampling fails: an outlier off the sample leaves the size that of the grid alone.
    raster::Mesh cloud = grid_cloud(1500);
    const double grid = sized(cloud);
    cloud.positions[1] = glm::vec3(4.0F, 0.0F, 0.0F);  // far out to the right, at an odd index
    EXPECT_DOUBLE_EQ(sized(cloud), grid);
    cloud.positions[2] = cloud.positions[1];  // on the sample: the box takes it in
    EXPECT_GT(sized(cloud), grid);
}

TEST(PointSizing, ACloudUnderTwiceTheSampleIsSizedFromEveryPoint) {
    raster::Mesh cloud = grid_cloud(1000);  // a million points: each one counts
    const double grid = sized(cloud);
    cloud.positions[1].x = 4.0F;
    EXPECT_GT(sized(cloud), grid);
}
