// Rendering on several threads and encoding on several: the same pictures and the same files
// whatever the count.
#include <raster/geometry/shapes.hpp>
#include <raster/io/obj_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include <raster/shade/shaders.hpp>
#include "rasterize/setup_perspective.hpp"

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using raster::Framebuffer;

namespace {

constexpr int kWidth = 161, kHeight = 97;  // odd sizes: bands of unequal height

template <typename Scene>
Framebuffer rendered(const Scene& scene, int threads, int width = kWidth, int height = kHeight) {
    Framebuffer image(width, height);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, {threads});
    return image;
}

}  // namespace

TEST(Threads, EveryThreadCountDrawsTheSamePicture) {
    for (const std::string_view name : {"two-spheres", "torus", "shaders", "point-lights", "faceted-sphere"}) {
        const raster::Scene scene = raster::DiaryScene(name).frame(kWidth, kHeight, 37, 360);
        const Framebuffer one = rendered(scene, 1);
        const raster::PerspectiveScene wide = raster::in_perspective(scene, kWidth, kHeight, 70.0);
        const Framebuffer one_wide = rendered(wide, 1);
        for (const int threads : {2, 3, 7, 0, kHeight}) {
            EXPECT_EQ(rendered(scene, threads), one) << name << " on " << threads << " threads";
            EXPECT_EQ(rendered(wide, threads), one_wide) << name << " in perspective on " << threads << " threads";
        }
    }
    for (const raster::SeedSceneInfo& info : raster::seed_scenes()) {
        const raster::PerspectiveScene scene = raster::SeedScene(info.name).frame(kWidth, kHeight, 50, info.frames);
        const Framebuffer one = rendered(scene, 1);
        for (const int threads : {2, 5})
            EXPECT_EQ(rendered(scene, threads), one) << info.name << " on " << threads << " threads";
    }
}

// A tall image is drawn in many strips of rows: together they draw what one pass of every
// triangle over the whole image draws, for triangles across strip edges and those clipped by
// the near plane too.
TEST(Threads, StripsTogetherDrawWhatOnePassOverTheWholeImageDraws) {
    constexpr int width = 90, height = 700;  // strips of 64 rows: eleven, the last short
    const raster::PerspectiveCamera camera = raster::PerspectiveCamera::look_at(
        width, height, {0.2F, 0.5F, -0.9F}, glm::vec3(0.0F), {0, 1, 0}, {70.0, 0.2, 10.0});
    const raster::IntensityMaterial material{{200, 120, 40}, 0.2F, 0.8F, std::nullopt};
    const std::vector<raster::DirectionalLight> lights{{glm::normalize(glm::vec3(1, 1, -1)), 1.0F}};
    const raster::Mesh torus = raster::torus(48, 32);
    const glm::mat4 model = glm::rotate(glm::mat4(1.0F), 0.6F, glm::vec3(1, 0, 0));
    raster::PerspectiveScene scene{camera, {10, 20, 30}, lights, {}, {}};
    scene.objects.push_back(
        {std::make_shared<const raster::Mesh>(torus), model, material, raster::ShadingMethod::flat});

    Framebuffer whole(width, height);
    whole.clear(scene.background);
    raster::DepthBuffer whole_depth;
    whole_depth.prepare(width, height);
    const raster::IntensityLighting lighting(material, lights, -camera.direction());
    const raster::Mesh mesh = raster::posed(torus, model);
    raster::detail::draw_facets_in_perspective(whole, &whole_depth, camera, mesh, raster::FlatShader{&lighting});
    int drawn = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) drawn += whole.pixel(x, y) == scene.background ? 0 : 1;
    }
    ASSERT_GT(drawn, width * height / 4);  // the torus fills much of the image, near plane cutting it
    for (const int threads : {1, 3}) EXPECT_EQ(rendered(scene, threads, width, height), whole) << threads << " threads";
}

TEST(Threads, ARenderReturnsTheSameFacetCountAndRefusesANegativeCount) {
    const raster::Scene scene = raster::DiaryScene("two-spheres").still(kWidth, kHeight);
    Framebuffer image(kWidth, kHeight);
    raster::DepthBuffer depth;
    const std::size_t one = raster::render(image, scene, depth, {1});
    EXPECT_GT(one, 0U);
    EXPECT_EQ(raster::render(image, scene, depth, {4}), one);
    EXPECT_THROW(raster::render(image, scene, depth, {-1}), std::invalid_argument);
}

// A Renderer keeps its threads and depth buffer between frames, and draws what render() draws,
// frame after frame, through changes of size and of camera.
TEST(Threads, ARendererDrawsWhatRenderDrawsFrameAfterFrame) {
    const raster::DiaryScene torus("torus");
    for (const int threads : {1, 3}) {
        raster::Renderer renderer({threads});
        EXPECT_EQ(renderer.threads(), threads);
        for (int i = 0; i < 4; ++i) {
            const int width = kWidth + 20 * (i % 2), height = kHeight - 10 * (i % 2);  // the size changes every frame
            const raster::Scene scene = torus.frame(width, height, 40 * i, 360);
            Framebuffer expected(width, height), image(width, height);
            raster::DepthBuffer depth;
            raster::render(expected, scene, depth, {1});
            EXPECT_EQ(renderer.render(image, scene), raster::render(expected, scene, depth, {1}));
            EXPECT_EQ(image, expected) << "frame " << i << " on " << threads << " threads";
            EXPECT_EQ(renderer.depth().at(width / 2, height / 2), depth.at(width / 2, height / 2));
            const raster::PerspectiveScene wide = raster::in_perspective(scene, width, height, 60.0);
            raster::render(expected, wide, depth, {1});
            renderer.render(image, wide);
            EXPECT_EQ(image, expected) << "frame " << i << " in perspective on " << threads << " threads";
        }
    }
    EXPECT_THROW(raster::Renderer({-1}), std::invalid_argument);
    EXPECT_EQ(raster::Renderer({100000}).threads(), raster::kMaxThreads);
}

TEST(Threads, ParallelAnimationsDecodeToEveryFrameAndMatchWhateverTheThreadCount) {
    std::vector<Framebuffer> frames;
    for (int i = 0; i < 12; ++i) {
        frames.emplace_back(90, 70);
        raster::render_tumble_frame(frames.back(), i, 12, raster::CubeStyle::filled);
    }
    frames.push_back(frames.back());  // an unchanged frame keeps its place
    const test_support::ScratchDir dir;
    std::vector<std::uint8_t> first;
    for (const int threads : {1, 2, 5}) {
        raster::AnimationEncoder encoder(90, 70, 20, {raster::Effort::fast, raster::AnimationPath::parallel, threads});
        for (const Framebuffer& frame : frames) encoder.add_frame(frame);
        const std::vector<std::uint8_t> bytes = encoder.finish();
        if (first.empty()) first = bytes;
        EXPECT_EQ(bytes, first) << threads << " threads";
    }
    test_support::write_text(dir / "p.webp", std::string(first.begin(), first.end()));
    const raster::DecodedWebp decoded = raster::read_webp(dir / "p.webp");
    ASSERT_EQ(decoded.frames.size(), frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) {
        EXPECT_EQ(decoded.frames[i].image, frames[i]) << "frame " << i;
        EXPECT_EQ(decoded.frames[i].start_ms, static_cast<int>(i) * 20);
        EXPECT_EQ(decoded.frames[i].duration_ms, 20);
    }
    EXPECT_THROW(raster::AnimationEncoder(8, 8, 20, {raster::Effort::fast, raster::AnimationPath::parallel, -1}),
                 std::invalid_argument);
}
