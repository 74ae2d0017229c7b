#include <raster/camera/ortho_camera.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using raster::OrthoCamera;

TEST(OrthoCamera, WorldOriginLandsOnTheCentrePixel) {
    EXPECT_EQ(OrthoCamera(800, 600).pixel_from_world({0, 0, 0}), glm::ivec2(400, 300));
    EXPECT_EQ(OrthoCamera(11, 7).pixel_from_world({0, 0, 0}), glm::ivec2(5, 3));
}

TEST(OrthoCamera, UnitSquareCornersSpanTheShorterSideWithYFlipped) {
    const OrthoCamera camera(800, 600);
    EXPECT_EQ(camera.pixel_from_world({-1, 1, 0}), glm::ivec2(100, 0));
    EXPECT_EQ(camera.pixel_from_world({1, 1, 0}), glm::ivec2(699, 0));
    EXPECT_EQ(camera.pixel_from_world({-1, -1, 0}), glm::ivec2(100, 599));
    EXPECT_EQ(camera.pixel_from_world({1, -1, 0}), glm::ivec2(699, 599));
}

TEST(OrthoCamera, PortraitImagesAreLetterboxedInsteadOfPillarboxed) {
    const OrthoCamera camera(600, 800);
    EXPECT_EQ(camera.pixel_from_world({-1, 1, 0}), glm::ivec2(0, 100));
    EXPECT_EQ(camera.pixel_from_world({1, -1, 0}), glm::ivec2(599, 699));
}

TEST(OrthoCamera, EqualWorldSpansGiveEqualPixelSpansOnBothAxes) {
    const OrthoCamera camera(800, 600);
    const glm::dvec2 origin = camera.screen_from_world({0, 0, 0});
    const glm::dvec2 right = camera.screen_from_world({0.5F, 0, 0});
    const glm::dvec2 up = camera.screen_from_world({0, 0.5F, 0});
    EXPECT_DOUBLE_EQ(right.x - origin.x, origin.y - up.y);
    EXPECT_DOUBLE_EQ(camera.scale(), 299.5);
}

TEST(OrthoCamera, DepthDoesNotMoveAPointOnScreen) {
    const OrthoCamera camera(800, 600);
    for (const float z : {-100.0F, -1.0F, 0.0F, 0.25F, 1.0F, 1e6F}) {
        EXPECT_EQ(camera.subpixel_from_world({0.3F, -0.7F, z}), camera.subpixel_from_world({0.3F, -0.7F, 0}));
    }
}

TEST(OrthoCamera, LooksAlongPositiveZ) { EXPECT_EQ(OrthoCamera(8, 8).direction(), glm::vec3(0, 0, 1)); }

TEST(OrthoCamera, SnapsToTheNearestSubpixelWithHalvesUp) {
    EXPECT_EQ(raster::snap_to_subpixel({2.5, 1.0 / 512}), (raster::SubpixelPoint{640, 1}));
    EXPECT_EQ(raster::snap_to_subpixel({-1.0 / 512, -3.0 / 512}), (raster::SubpixelPoint{0, -1}));
}

// The snap takes its floor by truncation; it must agree with std::floor everywhere in range.
TEST(OrthoCamera, SnapsLikeStdFloorOnEitherSideOfZeroAndAtTheLimit) {
    const double limit = raster::kMaxSubpixelCoordinate;
    for (const double screen :
         {0.0, -0.0, 1.0 / 512, -1.0 / 512, -1.0 / 256, -3.0 / 512, 7.75, -7.75, -7.998046875, limit - 1.0 / 512,
          -limit + 1.0 / 1024, limit, -limit, limit + 1.0 / 1024, -limit - 1.0 / 256}) {
        const double expected = std::floor(screen * raster::kSubpixelOne + 0.5);
        const std::optional<raster::SubpixelPoint> snapped = raster::snap_to_subpixel({screen, -screen});
        const double expected_y = std::floor(-screen * raster::kSubpixelOne + 0.5);
        const double most = limit * raster::kSubpixelOne;
        if (std::abs(expected) <= most && std::abs(expected_y) <= most) {
            ASSERT_TRUE(snapped.has_value()) << screen;
            EXPECT_EQ(snapped->x, expected) << screen;
            EXPECT_EQ(snapped->y, expected_y) << screen;
        } else {
            EXPECT_FALSE(snapped.has_value()) << screen;
        }
    }
}

TEST(OrthoCamera, PixelsRoundHalvesTowardPositiveXAndY) {
    EXPECT_EQ(raster::nearest_pixel(*raster::snap_to_subpixel({2.5, 2.5})), glm::ivec2(3, 3));
    EXPECT_EQ(raster::nearest_pixel(*raster::snap_to_subpixel({-0.5, 2.49})), glm::ivec2(0, 2));
    EXPECT_EQ(raster::nearest_pixel(*raster::snap_to_subpixel({-1.5, -0.51})), glm::ivec2(-1, -1));
}

TEST(OrthoCamera, NonFiniteAndFarAwayPositionsGiveNoPixel) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const double far = raster::kMaxSubpixelCoordinate + 1.0;
    for (const glm::dvec2 screen : {glm::dvec2(nan, 0), glm::dvec2(0, nan), glm::dvec2(inf, 0), glm::dvec2(0, -inf),
                                    glm::dvec2(far, 0), glm::dvec2(0, -far)}) {
        EXPECT_FALSE(raster::snap_to_subpixel(screen).has_value()) << screen.x << ", " << screen.y;
    }
    EXPECT_TRUE(raster::snap_to_subpixel({far - 2.0, 1 - far}).has_value());
    const raster::OrthoCamera camera(800, 600);
    EXPECT_FALSE(camera.pixel_from_world({std::numeric_limits<float>::quiet_NaN(), 0, 0}).has_value());
    EXPECT_FALSE(camera.subpixel_from_world({0, std::numeric_limits<float>::infinity(), 0}).has_value());
}

TEST(OrthoCamera, RejectsEmptyNegativeAndExtremeSizes) {
    constexpr int kMin = std::numeric_limits<int>::min();
    constexpr int kMax = std::numeric_limits<int>::max();
    for (const auto& [width, height] : {std::pair{0, 600},
                                        {800, 0},
                                        {-1, 600},
                                        {800, -600},
                                        {kMin, 600},
                                        {800, kMin},
                                        {kMin, kMin},
                                        {kMax, 600},
                                        {800, kMax},
                                        {raster::kMaxSubpixelCoordinate + 1, 600}}) {
        EXPECT_THROW(OrthoCamera(width, height), std::invalid_argument) << width << "x" << height;
    }
    EXPECT_NO_THROW(OrthoCamera(1, 1));
    EXPECT_NO_THROW(OrthoCamera(raster::kMaxSubpixelCoordinate, raster::kMaxSubpixelCoordinate));
}

TEST(LookAtCamera, TheDefaultEyeRendersExactlyLikeTheFixedCamera) {
    const OrthoCamera fixed(800, 600);
    const OrthoCamera looking = OrthoCamera::look_at(800, 600, {0, 0, -1});
    for (const glm::vec3 p : {glm::vec3(0.3F, -0.7F, 0.1F), glm::vec3(-1, 1, 5), glm::vec3(0.123F, 0.456F, -0.789F)}) {
        EXPECT_EQ(looking.subpixel_from_world(p), fixed.subpixel_from_world(p));
        EXPECT_EQ(looking.view_from_world(p), fixed.view_from_world(p));
        // And both are the fixed camera's formula, centre + s (x, -y), bit for bit.
        const glm::dvec2 formula(399.5 + 299.5 * double{p.x}, 299.5 - 299.5 * double{p.y});
        EXPECT_EQ(fixed.screen_from_world(p), formula);
    }
    EXPECT_EQ(looking.direction(), fixed.direction());
}

TEST(LookAtCamera, BuildsALeftHandedBasisWithUpKeptUp) {
    const OrthoCamera camera = OrthoCamera::look_at(101, 101, {1, 0, 0});  // from +X toward the origin
    EXPECT_NEAR(glm::distance(camera.direction(), glm::vec3(-1, 0, 0)), 0.0F, 1e-7F);
    // Looking along -X with +Y up, +Z is to the right: left-handed.
    const glm::dvec3 view = camera.view_from_world({0, 0, 1});
    EXPECT_NEAR(view.x, 1.0, 1e-12);
    EXPECT_NEAR(view.y, 0.0, 1e-12);
    EXPECT_NEAR(view.z, 1.0, 1e-12) << "depth is the distance from the eye along the view";
    EXPECT_NEAR(camera.view_from_world({0, 1, 0}).y, 1.0, 1e-12);
}

TEST(LookAtCamera, EyeOnTheTargetOrOnTheUpAxisIsAClearError) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const auto message = [](glm::vec3 eye) {
        try {
            (void)OrthoCamera::look_at(10, 10, eye);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message({0, 0, 0}), "camera eye and target coincide");
    EXPECT_EQ(message({0, 2, 0}), "camera looks straight along its up direction; move the eye off that axis");
    EXPECT_EQ(message({0, -2, 0}), "camera looks straight along its up direction; move the eye off that axis");
    EXPECT_EQ(message({nan, 0, -1}), "camera eye, target and up must be finite");
}

// An orbit over the pole: Gram-Schmidt fails only exactly on the axis; a hair away the basis is
// still orthonormal and every point lands on a finite pixel.
TEST(LookAtCamera, AnOrbitOverThePoleStaysFiniteUntilExactlyOnTheAxis) {
    for (const double tilt : {1e-2, 1e-4, 1e-6}) {
        const glm::vec3 eye(0.0F, static_cast<float>(std::cos(tilt)), static_cast<float>(-std::sin(tilt)));
        const OrthoCamera camera = OrthoCamera::look_at(800, 600, eye);
        EXPECT_NEAR(glm::length(camera.direction()), 1.0F, 1e-6F) << tilt;
        EXPECT_NEAR(glm::dot(camera.direction(), glm::vec3(0, -1, 0)), 1.0F, 1e-3F) << tilt;
        EXPECT_TRUE(camera.pixel_from_world({0.5F, 0.5F, 0.5F}).has_value()) << tilt;
    }
    EXPECT_THROW((void)OrthoCamera::look_at(800, 600, {0, 1, 0}), std::invalid_argument);
}
