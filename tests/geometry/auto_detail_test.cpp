#include <raster/geometry/analytic_shape.hpp>
#include <raster/render/auto_detail.hpp>
#include <raster/scenes/diary_scenes.hpp>

#include "exact_surface.hpp"
#include "scene_lab.hpp"

#include <cmath>
#include <limits>
#include <gtest/gtest.h>

using raster::DetailChoice;
using raster::ShadingMethod;
using raster::ShapeKind;

namespace {

struct Posed {
    ShapeKind shape;
    raster::Scene scene;
    [[nodiscard]] const raster::SceneObject& object() const { return scene.objects.front(); }
    [[nodiscard]] DetailChoice choose() const {
        return raster::choose_detail(shape, object().model, scene.camera,
                                     std::get<raster::IntensityMaterial>(object().material), scene.lights);
    }
    [[nodiscard]] double silhouette_px(int level) const {
        return raster::surface_deviation(shape, raster::tessellate(shape, level)) * scene.camera.scale() *
               raster::model_stretch(object().model).most;
    }
    [[nodiscard]] double shading(int level, ShadingMethod method) const {
        const raster::IntensityLighting lighting(std::get<raster::IntensityMaterial>(object().material), scene.lights,
                                                 -scene.camera.direction());
        const raster::Mesh mesh = raster::posed(raster::tessellate(shape, level), object().model);
        return raster::shading_error_levels(shape, mesh, object().model, scene.camera, method, lighting);
    }
};

Posed still(std::string_view name, ShapeKind shape, int width, int height) {
    return {shape, raster::DiaryScene(name).still(width, height)};
}

}  // namespace

// The diary's fixed torus(48, 32) is fine at 800 x 600 in the original's eyes, but its outline
// strays most of a pixel there and more at 1080p; the automatic choice stays inside both targets.
TEST(AutoDetail, MeetsBothTolerancesWhereTheDiaryDetailDoesNot) {
    const Posed torus = still("torus", ShapeKind::torus, 1920, 1080);
    EXPECT_GT(torus.silhouette_px(4), 1.0);
    EXPECT_GT(torus.shading(4, ShadingMethod::phong), 1.0);
    const DetailChoice choice = torus.choose();
    EXPECT_LT(choice.silhouette_px, raster::kSilhouetteTolerancePx);
    EXPECT_LT(choice.shading_levels, raster::kShadingToleranceLevels);
    EXPECT_NEAR(choice.silhouette_px, torus.silhouette_px(choice.level), 1e-9);
}

TEST(AutoDetail, NothingCoarserOrCheaperMeetsTheTargets) {
    for (const Posed& posed :
         {still("phong-sphere", ShapeKind::sphere, 800, 600), still("smooth-sphere", ShapeKind::sphere, 800, 600)}) {
        const DetailChoice choice = posed.choose();
        ASSERT_GT(choice.level, 0);
        const int coarser = choice.level - 1;
        if (posed.silhouette_px(coarser) < raster::kSilhouetteTolerancePx) {
            for (const ShadingMethod method : {ShadingMethod::flat, ShadingMethod::gouraud, ShadingMethod::phong}) {
                EXPECT_GE(posed.shading(coarser, method), raster::kShadingToleranceLevels);
            }
        }
        for (int method = 0; method < static_cast<int>(choice.shading); ++method) {
            EXPECT_GE(posed.shading(choice.level, static_cast<ShadingMethod>(method)), raster::kShadingToleranceLevels);
        }
    }
}

TEST(AutoDetail, BiggerOnScreenNeverGetsACoarserMesh) {
    int previous = 0;
    for (const int side : {100, 300, 600, 1200, 2400}) {
        const DetailChoice choice = still("phong-sphere", ShapeKind::sphere, side, side).choose();
        EXPECT_GE(choice.level, previous) << side;
        previous = choice.level;
    }
}

// The estimate sees coarse meshes for what they are: the octahedron and its first split are
// tens of levels off, as the lab measures them (123 and 83, 102 and 50 levels at most).
TEST(AutoDetail, TheEstimateSeesTheErrorsOfCoarseMeshes) {
    const Posed sphere = still("phong-sphere", ShapeKind::sphere, 800, 600);
    for (const int level : {0, 1}) {
        EXPECT_GT(sphere.shading(level, ShadingMethod::gouraud), 30.0) << level;
        EXPECT_GT(sphere.shading(level, ShadingMethod::phong), 30.0) << level;
    }
}

// Gouraud interpolates a highlight it cannot hold: at the level where Phong meets the target,
// Gouraud misses it by ten times.
TEST(AutoDetail, GouraudMissesTheShadingTargetWherePhongMeetsIt) {
    const Posed sphere = still("phong-sphere", ShapeKind::sphere, 800, 600);
    EXPECT_LT(sphere.shading(5, ShadingMethod::phong), raster::kShadingToleranceLevels);
    EXPECT_GT(sphere.shading(5, ShadingMethod::gouraud), 10.0 * raster::kShadingToleranceLevels);
}

// The estimate is checked against the ray-cast surface: inside the outline no pixel of the
// automatic choice is more than one level (after rounding) from the exact one.
TEST(AutoDetail, TheRayCastSurfaceAgreesWithinOneLevelInsideTheOutline) {
    constexpr int kWidth = 320, kHeight = 240;
    const Posed sphere = still("phong-sphere", ShapeKind::sphere, kWidth, kHeight);
    const DetailChoice choice = sphere.choose();
    raster::Scene scene = sphere.scene;
    scene.background = {255, 0, 255};
    scene.objects.front().mesh =
        std::make_shared<const raster::Mesh>(raster::tessellate(ShapeKind::sphere, choice.level));
    scene.objects.front().shading = choice.shading;
    raster::Framebuffer image(kWidth, kHeight);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth);
    const std::vector<lab::ExactObject> exact{
        {ShapeKind::sphere, sphere.object().model, std::get<raster::IntensityMaterial>(sphere.object().material)}};
    const lab::ExactImage reference = lab::ray_cast(scene.camera, kWidth, kHeight, exact, scene.lights, {255, 0, 255});
    int compared = 0;
    for (int y = 1; y + 1 < kHeight; ++y) {
        for (int x = 1; x + 1 < kWidth; ++x) {
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    interior = interior && image.pixel(x + dx, y + dy) != raster::Rgb{255, 0, 255} &&
                               reference.covered[static_cast<std::size_t>((y + dy) * kWidth + x + dx)] != 0;
                }
            }
            if (!interior) continue;
            ++compared;
            const raster::Rgb a = image.pixel(x, y), b = reference.colour.pixel(x, y);
            ASSERT_LE(std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}), 1) << x << ", " << y;
        }
    }
    EXPECT_GT(compared, 10000);
}

TEST(AutoDetail, ClipsPlanOnceForEveryFrameAndNonFiniteModelsAreAClearError) {
    const raster::DiaryScene squash("squash");
    std::vector<raster::Scene> frames;
    for (int i = 0; i < 720; i += 60) frames.push_back(squash.frame(400, 300, i, 720));
    const raster::DetailPlan plan = raster::plan_detail(frames);
    ASSERT_EQ(plan.choices.size(), 1U);
    ASSERT_TRUE(plan.choices[0].has_value());
    for (const raster::Scene& frame : frames) {
        const raster::SceneObject& object = frame.objects.front();
        const DetailChoice alone =
            raster::choose_detail(ShapeKind::sphere, object.model, frame.camera,
                                  std::get<raster::IntensityMaterial>(object.material), frame.lights);
        EXPECT_GE(plan.choices[0]->level, alone.level);
        EXPECT_GE(plan.choices[0]->shading, alone.shading);
    }
    const raster::Scene detailed = raster::with_detail(frames[3], plan);
    EXPECT_EQ(detailed.objects.front().mesh, plan.meshes[0]);
    glm::mat4 broken(1.0F);
    broken[0][0] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW((void)raster::choose_detail(ShapeKind::torus, broken, frames[0].camera,
                                             std::get<raster::IntensityMaterial>(frames[0].objects[0].material),
                                             frames[0].lights),
                 std::invalid_argument);
}

// The depth formats' failure points, from the lab: 16-bit codes lose planes 1e-5 apart and
// crossing at 0.01 degrees, which 32-bit float view depth keeps; float fails in turn at a gap
// of 1e-7, below its resolution at depth 1.
TEST(DepthFormats, SixteenBitFixedLosesNearlyCoplanarPlanesThatFloatKeeps) {
    const auto wrong = [rows = lab::measure_depth(1)](const std::string& scene, double parameter,
                                                      const std::string& format) {
        for (const lab::DepthRow& row : rows) {
            if (row.scene == scene && std::abs(row.parameter / parameter - 1.0) < 1e-9 && row.format == format)
                return row.wrong_pixels;
        }
        return std::int64_t{-1};
    };
    EXPECT_GT(wrong("gap", 1e-5, "fixed16"), 1000);
    EXPECT_EQ(wrong("gap", 1e-5, "float32"), 0);
    EXPECT_GT(wrong("crossing", 0.01, "fixed16"), 100);
    EXPECT_EQ(wrong("crossing", 0.01, "float32"), 0);
    EXPECT_GT(wrong("gap", 1e-7, "float32"), 1000);
}

// Phase 2 surfaces are planned by their linear-light colour after the sRGB encoding: an
// emissive-only marker looks the same however it is shaded, so the cheapest shading is exact;
// the lit torus needs Phong, and the plan for a scene is what each object would choose alone.
TEST(AutoDetail, PhaseTwoSurfacesArePlannedByTheirEncodedColour) {
    const raster::Scene lamp = raster::DiaryScene("point-light").still(800, 600);
    ASSERT_EQ(lamp.objects.size(), 2U);
    const raster::SceneObject& marker = lamp.objects[1];
    const auto& gold = std::get<raster::LinearMaterial>(marker.material);
    const DetailChoice dot =
        raster::choose_detail(ShapeKind::sphere, marker.model, lamp.camera, gold, lamp.lights, lamp.point_lights);
    EXPECT_EQ(dot.shading, ShadingMethod::flat);
    EXPECT_EQ(dot.shading_levels, 0.0);

    const raster::Scene torus = raster::DiaryScene("point-lights").still(400, 300);
    const raster::SceneObject& ring = torus.objects.front();
    const auto& palette = std::get<raster::LinearMaterial>(ring.material);
    const DetailChoice alone =
        raster::choose_detail(ShapeKind::torus, ring.model, torus.camera, palette, torus.lights, torus.point_lights);
    EXPECT_EQ(alone.shading, ShadingMethod::phong);
    EXPECT_LT(alone.shading_levels, raster::kShadingToleranceLevels);
    // Flat shading on the same mesh is visibly off, measured in levels of the written bytes.
    const raster::LinearLighting lighting(palette, torus.lights, torus.point_lights, -torus.camera.direction());
    const raster::Mesh mesh = raster::posed(raster::tessellate(ShapeKind::torus, alone.level), ring.model);
    EXPECT_GT(
        raster::shading_error_levels(ShapeKind::torus, mesh, ring.model, torus.camera, ShadingMethod::flat, lighting),
        2.0);

    const raster::DetailPlan plan = raster::plan_detail(std::vector<raster::Scene>{torus});
    ASSERT_EQ(plan.choices.size(), 1U);
    ASSERT_TRUE(plan.choices[0].has_value());
    EXPECT_EQ(plan.choices[0]->level, alone.level);
    EXPECT_EQ(plan.choices[0]->shading, alone.shading);
}
