// Viewport, clipping and 1/w share one scene set-up; stays whole so that they read together.
// The perspective camera, clipping in homogeneous space and interpolation through 1/w.
#include "rasterize/setup_perspective.hpp"

#include <raster/shade/shaders.hpp>

#include <raster/geometry/shapes.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>

#include "recording_shader.hpp"
#include "support/picture.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::PerspectiveCamera;
using test_support::looks_like;

namespace {

const PerspectiveCamera::Lens kRightAngle{90.0, 0.1, 1000.0};

PerspectiveCamera ahead(int width, int height, PerspectiveCamera::Lens lens = kRightAngle) {
    return PerspectiveCamera::look_at(width, height, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, lens);
}

// White wherever the surface shows, whatever the light: emissive only.
raster::LinearMaterial white() { return {{1, 1, 1}, {0, 0, 0}, {0, 0, 0}, std::nullopt}; }

raster::Mesh triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    raster::Mesh mesh;
    mesh.positions = {a, b, c};
    mesh.normals.assign(3, glm::vec3(0, 1, 0));
    mesh.facets = {{{0, 1, 2}, glm::vec3(0, 1, 0)}};
    mesh.surface = raster::Surface::faceted;
    mesh.convex = true;
    return mesh;
}

std::size_t draw(Framebuffer& image, const PerspectiveCamera& camera, std::vector<raster::Mesh> meshes) {
    raster::PerspectiveScene scene{camera, {0, 0, 0}, {}, {}, {}};
    for (raster::Mesh& mesh : meshes) {
        scene.objects.push_back({std::make_shared<const raster::Mesh>(std::move(mesh)), glm::mat4(1.0F), white(),
                                 raster::ShadingMethod::flat});
    }
    raster::DepthBuffer depth;
    return raster::render(image, scene, depth);
}

const std::map<char, raster::Rgb> kWhite{{'#', {255, 255, 255}}};

}  // namespace

// NDC x = -1 is the left edge of the first column and y = +1 the top edge of the first row, so
// with pixel centres on whole numbers the view axis lands on ((W - 1) / 2, (H - 1) / 2).
TEST(Perspective, ViewportFollowsOpenGlWithPixelCentresOnWholeNumbers) {
    const PerspectiveCamera camera = ahead(8, 4);
    const auto off = [&](glm::vec3 p, glm::dvec2 expected) {
        return glm::distance(camera.screen_from_clip(camera.clip_from_world(p)), expected);
    };
    EXPECT_LT(off({0, 0, 1}, {3.5, 1.5}), 1e-12);
    // tan 45 degrees = 1: at distance 1 the view is 2 high and, at aspect 2, 4 wide.
    EXPECT_LT(off({-2, 1, 1}, {-0.5, -0.5}), 1e-12);
    EXPECT_LT(off({2, -1, 1}, {7.5, 3.5}), 1e-12);
    EXPECT_LT(off({-4, 2, 2}, {-0.5, -0.5}), 1e-12);  // twice as far, twice as wide
    // Depth: NDC z runs from 0 at the near plane to 1 at the far plane; w is the view depth.
    const glm::dvec4 near = camera.clip_from_world({0, 0, 0.1F});
    const glm::dvec4 far = camera.clip_from_world({0, 0, 1000});
    EXPECT_NEAR(near.z / near.w, 0.0, 1e-7);  // 0.1F is not quite 0.1
    EXPECT_NEAR(far.z / far.w, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(camera.clip_from_world({3, 2, 7}).w, 7.0);
}

TEST(Perspective, FirstPersonYawTurnsTowardXAndPitchRaisesTheView) {
    const auto look = [](double pitch, double yaw) {
        return PerspectiveCamera::first_person(64, 48, {1, 2, 3}, pitch, yaw, kRightAngle).direction();
    };
    EXPECT_NEAR(glm::distance(look(0, 0), glm::vec3(0, 0, 1)), 0.0F, 1e-6F);
    EXPECT_NEAR(glm::distance(look(0, std::numbers::pi / 2), glm::vec3(1, 0, 0)), 0.0F, 1e-6F);
    EXPECT_NEAR(glm::distance(look(std::numbers::pi / 4, 0), glm::normalize(glm::vec3(0, 1, 1))), 0.0F, 1e-6F);
    EXPECT_EQ(PerspectiveCamera::first_person(64, 48, {1, 2, 3}, 0, 0, kRightAngle).eye(), glm::vec3(1, 2, 3));
    // Far from the origin the direction still survives the look-at target's rounding to float.
    const glm::vec3 far_view =
        PerspectiveCamera::first_person(64, 48, {1e6F, 5e5F, -3e6F}, 0.2, 0.3, kRightAngle).direction();
    const glm::vec3 expected(std::sin(0.3) * std::cos(0.2), std::sin(0.2), std::cos(0.3) * std::cos(0.2));
    EXPECT_LT(glm::distance(far_view, expected), 1e-6F);
}

TEST(Perspective, BadLensesAndPosesAreClearErrors) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    for (const PerspectiveCamera::Lens lens :
         {PerspectiveCamera::Lens{0, 0.1, 10}, PerspectiveCamera::Lens{180, 0.1, 10},
          PerspectiveCamera::Lens{nan, 0.1, 10}, PerspectiveCamera::Lens{60, 0, 10},
          PerspectiveCamera::Lens{60, -1, 10}, PerspectiveCamera::Lens{60, 1, 1}, PerspectiveCamera::Lens{60, 1, inf},
          PerspectiveCamera::Lens{60, nan, 10}, PerspectiveCamera::Lens{60, 1e-19, 10},
          PerspectiveCamera::Lens{60, 1, 1e19}}) {
        EXPECT_THROW((void)ahead(8, 8, lens), std::invalid_argument)
            << lens.fov_y_degrees << " " << lens.near << " " << lens.far;
    }
    EXPECT_THROW((void)PerspectiveCamera::look_at(8, 8, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}, kRightAngle),
                 std::invalid_argument);
    EXPECT_THROW((void)PerspectiveCamera::look_at(8, 8, {0, 0, 0}, {0, 5, 0}, {0, 1, 0}, kRightAngle),
                 std::invalid_argument);
    EXPECT_THROW((void)PerspectiveCamera::first_person(8, 8, {0, 0, 0}, std::numbers::pi / 2, 0, kRightAngle),
                 std::invalid_argument);
    EXPECT_THROW((void)PerspectiveCamera::first_person(8, 8, {0, 0, 0}, 0, nan, kRightAngle), std::invalid_argument);
    EXPECT_THROW((void)PerspectiveCamera::look_at(0, 8, {0, 0, 0}, {0, 0, 1}, {0, 1, 0}, kRightAngle),
                 std::invalid_argument);
}

// A floor from far behind the eye to far ahead crosses w = 0 and the near plane; clipped, it
// covers exactly the rows below the horizon, with no stray spans above it.
TEST(Clipping, AFloorThroughTheEyeFillsTheRowsBelowTheHorizon) {
    Framebuffer image(8, 8);
    const float y = -1.0F, reach = 100.0F;
    EXPECT_EQ(
        draw(image, ahead(8, 8),
             {raster::ground_quad({-reach, y, -reach}, {reach, y, -reach}, {reach, y, reach}, {-reach, y, reach})}),
        2U);
    EXPECT_TRUE(looks_like(
        image, {"........", "........", "........", "........", "########", "########", "########", "########"},
        kWhite));
}

TEST(Clipping, TrianglesBehindTheEyeOrBeyondFarDrawNothing) {
    Framebuffer image(16, 16);
    EXPECT_EQ(draw(image, ahead(16, 16), {triangle({-1, -1, -2}, {0, 1, -2}, {1, -1, -2})}), 0U);
    EXPECT_EQ(draw(image, ahead(16, 16), {triangle({-1, -1, 2000}, {0, 1, 2000}, {1, -1, 2000})}), 0U);
    EXPECT_EQ(draw(image, ahead(16, 16), {triangle({-1, -1, 0.05F}, {0, 1, 0.05F}, {1, -1, 0.05F})}),
              0U);  // before near
    EXPECT_TRUE(looks_like(image, std::vector<std::string>(16, "................"), kWhite));
}

// A triangle with one corner behind the eye draws the same pixels as the part of it in front
// of the near plane, cut by hand.
TEST(Clipping, ATriangleCrossingTheEyeDrawsItsPartInFrontOfTheNearPlane) {
    const glm::vec3 a{-1, -1, 2}, b{0, -1, -2}, c{1, -1, 2};  // b is behind the eye
    Framebuffer clipped(32, 24);
    EXPECT_EQ(draw(clipped, ahead(32, 24), {triangle(a, c, b)}), 1U);  // clockwise seen from above
    // Where the edges a-b and b-c meet z = 0.1.
    const float t = (2.0F - 0.1F) / 4.0F;
    const glm::vec3 ab = a + (b - a) * t, bc = c + (b - c) * t;
    Framebuffer by_hand(32, 24);
    draw(by_hand, ahead(32, 24), {triangle(a, c, bc), triangle(a, bc, ab)});
    EXPECT_EQ(clipped, by_hand) << test_support::to_ascii_art(clipped, kWhite) << "\n"
                                << test_support::to_ascii_art(by_hand, kWhite);
    int covered = 0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 32; ++x) covered += clipped.pixel(x, y).r == 255 ? 1 : 0;
    }
    EXPECT_GT(covered, 50);
}

// A triangle thousands of times larger than the screen reaches past the guard band; clipped
// there, it still covers every pixel exactly once.
TEST(Clipping, HugeTrianglesAreClippedToTheGuardBandAndCoverTheScreen) {
    Framebuffer image(16, 12);
    const float far = 1e7F;
    const raster::Mesh huge = triangle({-far, -far, 1}, {0, far, 1}, {far, -far, 1});
    EXPECT_EQ(draw(image, ahead(16, 12), {huge}), 1U);
    EXPECT_TRUE(looks_like(image, std::vector<std::string>(12, "################"), kWhite));
    std::vector<glm::vec3> seen;
    raster::detail::draw_facets_in_perspective(image, nullptr, ahead(16, 12), huge, lab::RecordingShader{&seen});
    EXPECT_EQ(seen.size(), 16U * 12U);
}

// A floor triangle reaching beyond the far plane draws the same pixels as its part nearer than
// far, cut by hand.
TEST(Clipping, ATriangleCrossingTheFarPlaneDrawsItsPartNearerThanFar) {
    const PerspectiveCamera camera = ahead(32, 24, {90.0, 0.1, 10.0});
    const glm::vec3 a{-12, -4, 5}, b{0, -4, 15}, c{12, -4, 5};  // b is beyond far
    Framebuffer clipped(32, 24), by_hand(32, 24);
    EXPECT_EQ(draw(clipped, camera, {triangle(a, b, c)}), 1U);
    const glm::vec3 ab = a + (b - a) * 0.5F, cb = c + (b - c) * 0.5F;  // where the edges reach z = 10
    draw(by_hand, camera, {triangle(a, ab, cb), triangle(a, cb, c)});
    EXPECT_EQ(clipped, by_hand) << test_support::to_ascii_art(clipped, kWhite) << "\n"
                                << test_support::to_ascii_art(by_hand, kWhite);
    Framebuffer whole(32, 24);
    draw(whole, ahead(32, 24, {90.0, 0.1, 100.0}), {triangle(a, b, c)});
    EXPECT_NE(clipped, whole);  // with a farther far plane more of it shows
}

namespace {

// Keeps every point it is handed with its change per pixel in x, and writes the point's index.
struct FootprintRecorder {
    using Varying = glm::vec3;
    static constexpr bool kFacetNormal = false;
    std::vector<std::pair<glm::vec3, glm::vec3>>* seen;
    [[nodiscard]] Varying vertex(const raster::Corner& corner) const noexcept { return corner.position; }
    [[nodiscard]] raster::Rgb pixel(const glm::vec3& world, const glm::vec3& per_x, const glm::vec3&) const noexcept {
        const auto index = static_cast<std::uint32_t>(seen->size());
        seen->emplace_back(world, per_x);
        return {static_cast<std::uint8_t>(index >> 16), static_cast<std::uint8_t>(index >> 8),
                static_cast<std::uint8_t>(index)};
    }
};

}  // namespace

// The change per pixel a shader is handed (for mip levels) is the true derivative of the
// perspective-correct value: it matches the difference between neighbouring pixels.
TEST(PerspectiveInterpolation, ShadersGetTheExactChangePerPixel) {
    const PerspectiveCamera camera =
        PerspectiveCamera::look_at(40, 30, {0, 1, -1}, {0, 0, 3}, {0, 1, 0}, {70, 0.1, 100});
    raster::Mesh floor = raster::ground_quad({-2, 0, 0}, {2, 0, 0}, {2, 0, 20}, {-2, 0, 20});
    floor.surface = raster::Surface::smooth;
    Framebuffer image(40, 30);
    image.clear({255, 255, 255});
    std::vector<std::pair<glm::vec3, glm::vec3>> seen;
    raster::detail::draw_facets_in_perspective(image, nullptr, camera, floor, FootprintRecorder{&seen});
    int compared = 0;
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x + 1 < 40; ++x) {
            const std::uint32_t a = lab::recorded_index(image, x, y), b = lab::recorded_index(image, x + 1, y);
            if (a >= seen.size() || b >= seen.size()) continue;
            const glm::vec3 difference = seen[b].first - seen[a].first;
            const glm::vec3 mean_change =
                (seen[a].second + seen[b].second) * 0.5F;  // the derivative at the midpoint, to second order
            EXPECT_NEAR(mean_change.x, difference.x, 1e-3F + 0.01F * std::abs(difference.x)) << x << "," << y;
            EXPECT_NEAR(mean_change.z, difference.z, 1e-3F + 0.01F * std::abs(difference.z)) << x << "," << y;
            ++compared;
        }
    }
    EXPECT_GT(compared, 200);
}

// Under perspective, attributes are interpolated through 1/w: the world position a shader sees
// at each covered pixel lies on the line of sight through that pixel's centre.
TEST(PerspectiveInterpolation, TheSurfacePointAtEveryPixelIsOnItsLineOfSight) {
    const PerspectiveCamera camera =
        PerspectiveCamera::look_at(40, 30, {0, 1, -1}, {0, 0, 3}, {0, 1, 0}, {70, 0.1, 100});
    // A long floor receding from the camera: affine interpolation would be pixels off here.
    raster::Mesh floor = raster::ground_quad({-2, 0, 0}, {2, 0, 0}, {2, 0, 20}, {-2, 0, 20});
    floor.surface = raster::Surface::smooth;
    Framebuffer image(40, 30);
    std::vector<glm::vec3> seen;
    image.clear({255, 255, 255});
    raster::DepthBuffer depth;
    depth.prepare(40, 30);
    EXPECT_GT(raster::detail::draw_facets_in_perspective(image, &depth, camera, floor, lab::RecordingShader{&seen}),
              0U);
    ASSERT_GT(seen.size(), 100U);
    // Every written pixel's point projects back onto that pixel's centre, to within the 1/256 px
    // the corners were snapped by (interpolating linearly on screen would be pixels off here),
    // and the depth buffer holds that point's view depth.
    double worst = 0.0;
    std::size_t written = 0;
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 40; ++x) {
            const std::uint32_t index = lab::recorded_index(image, x, y);
            if (index >= seen.size()) continue;
            ++written;
            const glm::dvec2 at = camera.screen_from_clip(camera.clip_from_world(seen[index]));
            worst = std::max({worst, std::abs(at.x - x), std::abs(at.y - y)});
            const double view_depth = camera.view_from_world(seen[index]).z;
            EXPECT_NEAR(depth.at(x, y), view_depth, 1e-5 * view_depth) << x << ", " << y;
        }
    }
    EXPECT_EQ(written, seen.size());  // each pixel shaded once
    EXPECT_LT(worst, 1.0 / 256);
}

// At a tiny field of view the eye stands far back and the picture is the orthographic one.
TEST(Perspective, ANarrowViewOfADiaryScenelooksLikeItsOrthographicPicture) {
    for (const std::string_view name : {"two-spheres", "point-light", "shaders"}) {
        const raster::Scene scene = raster::DiaryScene(name).still(160, 120);
        Framebuffer flat(160, 120), narrow(160, 120), wide(160, 120);
        raster::DepthBuffer depth;
        raster::render(flat, scene, depth);
        raster::render(narrow, raster::in_perspective(scene, 160, 120, 0.01), depth);
        raster::render(wide, raster::in_perspective(scene, 160, 120, 60.0), depth);
        int differ_narrow = 0, differ_wide = 0;
        for (int y = 0; y < 120; ++y) {
            for (int x = 0; x < 160; ++x) {
                const raster::Rgb a = flat.pixel(x, y), b = narrow.pixel(x, y);
                differ_narrow += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 2 ? 1 : 0;
                differ_wide += a != wide.pixel(x, y) ? 1 : 0;
            }
        }
        EXPECT_LE(differ_narrow, 160 * 120 / 200) << name;  // at most 0.5 %: outline pixels
        EXPECT_GE(differ_wide, 160 * 120 / 20) << name;     // and a wide view really is different
    }
}
