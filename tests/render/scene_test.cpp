#include <raster/geometry/shapes.hpp>
#include <raster/rasterize/draw_mesh.hpp>
#include <raster/render/scene.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/palette.hpp>
#include <raster/scenes/scenes.hpp>
#include <raster/shade/shaders.hpp>

#include <glm/ext/matrix_transform.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::Scene;

namespace {

std::shared_ptr<const raster::Mesh> shared(raster::Mesh mesh) {
    return std::make_shared<const raster::Mesh>(std::move(mesh));
}

Scene one_object(std::shared_ptr<const raster::Mesh> mesh, const glm::mat4& model = glm::mat4(0.5F)) {
    Scene scene{raster::OrthoCamera(64, 48), {0, 0, 0}, {{{1, 1, -1}}}, {}, {}};
    scene.objects.push_back({std::move(mesh), model, raster::IntensityMaterial::shiny({52, 110, 210}, 0.15F, 100.0F)});
    scene.objects.back().model[3][3] = 1.0F;
    return scene;
}

int differing_pixels(const Framebuffer& a, const Framebuffer& b) {
    int count = 0;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) count += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
    }
    return count;
}

}  // namespace

TEST(DepthRule, ALoneConvexMeshNeverTouchesTheDepthBuffer) {
    for (const auto& mesh : {shared(raster::cube_mesh()), shared(raster::dodecahedron()), shared(raster::sphere(3))}) {
        const Scene scene = one_object(mesh);
        EXPECT_FALSE(raster::needs_depth(scene));
        Framebuffer image(64, 48);
        raster::DepthBuffer depth;
        EXPECT_GT(raster::render(image, scene, depth), 0U);
        EXPECT_FALSE(depth.allocated());
        // And skipping it is safe: with a depth test the pixels are the same.
        Framebuffer tested(64, 48);
        raster::DepthBuffer used;
        used.prepare(64, 48);
        tested.clear(scene.background);
        const raster::Mesh posed = raster::posed(*mesh, scene.objects[0].model);
        const raster::IntensityLighting lighting(std::get<raster::IntensityMaterial>(scene.objects[0].material),
                                                 scene.lights, -scene.camera.direction());
        raster::draw_mesh({tested, &used}, scene.camera, posed, raster::PhongShader{&lighting});
        EXPECT_EQ(differing_pixels(image, tested), 0);
    }
}

TEST(DepthRule, SeveralObjectsOrANonConvexMeshGetOneAndNeedIt) {
    // Seen from above with its near half drawn first, the torus hides its own far half.
    Scene torus = one_object(shared(raster::torus(24, 16)), glm::rotate(glm::mat4(0.8F), 3.14159F, glm::vec3(0, 1, 0)));
    torus.objects[0].model[3][3] = 1.0F;
    torus.camera = raster::OrthoCamera::look_at(64, 48, {0.0F, 0.5F, -1.0F});
    EXPECT_TRUE(raster::needs_depth(torus));
    // Three quarters round the orbit the eye is on the -X side: the big sphere, drawn first,
    // stands in front of the small one.
    const raster::DiaryScene two_spheres("two-spheres");
    const Scene pair = two_spheres.frame(64, 48, 434, 720);
    EXPECT_TRUE(raster::needs_depth(pair));
    for (const Scene& scene : {torus, pair}) {
        Framebuffer image(64, 48);
        raster::DepthBuffer depth;
        raster::render(image, scene, depth);
        EXPECT_TRUE(depth.allocated());
        // Without the depth test later facets paint over nearer ones: the picture changes.
        Framebuffer untested(64, 48);
        untested.clear(scene.background);
        for (const raster::SceneObject& object : scene.objects) {
            const raster::IntensityLighting lighting(std::get<raster::IntensityMaterial>(object.material), scene.lights,
                                                     -scene.camera.direction());
            raster::draw_mesh({untested, nullptr}, scene.camera, raster::posed(*object.mesh, object.model),
                              raster::PhongShader{&lighting});
        }
        EXPECT_GT(differing_pixels(image, untested), 0);
    }
}

// The cube's twelve facets, each pair painted in its face's palette colour, cover exactly the
// pixels the six quads do, in every frame of the tumble.
TEST(CubeMesh, TwelveFacetsDrawTheSixQuadsPixelForPixel) {
    const raster::Mesh cube = raster::cube_mesh();
    for (int frame = 0; frame < raster::kAnimationFrameCount; frame += 7) {
        Framebuffer quads(200, 150);
        raster::render_tumble_frame(quads, frame, raster::kAnimationFrameCount, raster::CubeStyle::filled);
        Framebuffer facets(200, 150);
        const raster::OrthoCamera camera(200, 150);
        const raster::Mesh posed = raster::posed(cube, raster::tumble_pose(frame, raster::kAnimationFrameCount));
        for (std::size_t slot = 0; slot < 6; ++slot) {
            raster::Mesh face = posed;
            face.facets = {posed.facets[2 * slot], posed.facets[2 * slot + 1]};
            const raster::IntensityLighting unlit({raster::kCubeFacePalette[slot], 1.0F, 0.0F, {}}, {}, {0, 0, -1});
            raster::draw_mesh({facets, nullptr}, camera, face, raster::FlatShader{&unlit});
        }
        ASSERT_EQ(differing_pixels(quads, facets), 0) << "frame " << frame;
    }
}

TEST(DrawMesh, MalformedMeshesAndMismatchedBuffersAreClearErrors) {
    Framebuffer image(8, 8);
    const raster::IntensityLighting lighting(raster::IntensityMaterial::matte({255, 255, 255}, 0.5F), {}, {0, 0, -1});
    const raster::OrthoCamera camera(8, 8);
    raster::Mesh missing_vertex = raster::cube_mesh();
    missing_vertex.facets[3].corners[1] = 8;
    EXPECT_THROW(raster::draw_mesh({image}, camera, missing_vertex, raster::FlatShader{&lighting}),
                 std::invalid_argument);
    raster::Mesh missing_normals = raster::sphere(1);
    missing_normals.normals.pop_back();
    EXPECT_THROW(raster::draw_mesh({image}, camera, missing_normals, raster::PhongShader{&lighting}),
                 std::invalid_argument);
    raster::DepthBuffer small;
    small.prepare(4, 8);
    EXPECT_THROW(raster::draw_mesh({image, &small}, camera, raster::sphere(1), raster::PhongShader{&lighting}),
                 std::invalid_argument);
}

TEST(DiaryScenes, EveryNameBuildsAndUnknownNamesListTheChoices) {
    for (const raster::SceneInfo& info : raster::diary_scenes()) {
        const raster::DiaryScene scene(info.name);
        EXPECT_EQ(scene.info().name, info.name);
        EXPECT_FALSE(scene.still(80, 60).objects.empty());
        EXPECT_FALSE(scene.frame(80, 60, info.frames - 1, info.frames).objects.empty());
    }
    try {
        (void)raster::DiaryScene("teapot");
        FAIL();
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("no scene 'teapot'; the scenes are lit-cube, dodecahedron"),
                  std::string::npos);
    }
    EXPECT_EQ(raster::diary_scenes().back().name, "shaders");
}

TEST(DiaryScenes, CubicEasingStartsSlowEndsSlowAndIsSymmetric) {
    EXPECT_DOUBLE_EQ(raster::ease_in_out_cubic(0.0), 0.0);
    EXPECT_DOUBLE_EQ(raster::ease_in_out_cubic(0.5), 0.5);
    EXPECT_DOUBLE_EQ(raster::ease_in_out_cubic(1.0), 1.0);
    EXPECT_DOUBLE_EQ(raster::ease_in_out_cubic(0.25), 0.0625);
    EXPECT_DOUBLE_EQ(raster::ease_in_out_cubic(0.75), 0.9375);
}

TEST(LitCube, TheStyleAndTheSceneAreOneRender) {
    for (int frame : {0, 45, 200}) {
        Framebuffer style(160, 120);
        raster::render_tumble_frame(style, frame, 360, raster::CubeStyle::lit);
        Framebuffer scene(160, 120);
        raster::DepthBuffer depth;
        raster::render(scene, raster::DiaryScene("lit-cube").frame(160, 120, frame, 360), depth);
        EXPECT_EQ(style, scene) << frame;
    }
}

// The exporters' default is the original's last animation (0.1.8 and 0.1.9): the torus(48, 32)
// scaled 0.8, one directional light and two point lights, the three.js palette on 0x444444,
// 360 frames, through the per-pixel Phong shader.
TEST(DiaryScenes, TheDefaultIsTheOriginalsFinalAnimation) {
    const raster::SceneInfo& info = raster::final_diary_scene();
    EXPECT_EQ(info.name, "point-lights");
    EXPECT_EQ(info.frames, 360);
    const raster::Scene frame = raster::DiaryScene(info.name).frame(80, 60, 0, info.frames);
    EXPECT_EQ(frame.background, (raster::Rgb{0x44, 0x44, 0x44}));
    ASSERT_EQ(frame.lights.size(), 1U);
    EXPECT_EQ(frame.lights[0].intensity, 0.5F);
    ASSERT_EQ(frame.point_lights.size(), 2U);
    EXPECT_EQ(frame.point_lights[0].intensity, 3.0F);
    EXPECT_EQ(frame.point_lights[1].intensity, 3.0F);
    ASSERT_EQ(frame.objects.size(), 1U);
    EXPECT_EQ(frame.objects[0].shading, raster::ShadingMethod::phong);
    EXPECT_EQ(frame.objects[0].mesh->facets.size(), 48U * 32U * 2U);
}
