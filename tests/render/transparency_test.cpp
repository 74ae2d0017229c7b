// Blend objects: every fragment kept per strip, sorted by depth and composited back to front in
// linear light over the opaque result (doc/conventions.md#transparency).
#include <raster/image/colour.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>
#include <gtest/gtest.h>

using raster::Framebuffer;
using raster::LinearRgb;

namespace {

constexpr int kSize = 9;

// An unlit square of `colour` at depth z facing the camera (which looks along +z), from -half
// to +half in x and y: the view spans -1..1, so half 2 fills it.
raster::SceneObject square(float z, LinearRgb colour, raster::Opacity opacity, float half = 2.0F,
                           glm::vec2 centre = {0.0F, 0.0F}) {
    auto mesh = std::make_shared<raster::Mesh>();
    const float x0 = centre.x - half, x1 = centre.x + half, y0 = centre.y - half, y1 = centre.y + half;
    mesh->positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    mesh->normals.assign(4, {0.0F, 0.0F, -1.0F});
    mesh->uvs = {{0.0F, 0.0F}, {1.0F, 0.0F}, {1.0F, 1.0F}, {0.0F, 1.0F}};
    const glm::vec3 behind(centre.x, centre.y, z + 1.0F);
    mesh->facets = {raster::facet_facing_away(mesh->positions, 0, 1, 2, behind),
                    raster::facet_facing_away(mesh->positions, 0, 2, 3, behind)};
    raster::SceneObject object{mesh, glm::mat4(1.0F), raster::LinearMaterial{{0, 0, 0}, colour, {0, 0, 0}, {}},
                               raster::ShadingMethod::unlit};
    object.opacity = opacity;
    return object;
}

raster::Opacity blend(float alpha) { return {raster::AlphaMode::blend, alpha, 0.5F}; }

raster::Scene scene_of(std::vector<raster::SceneObject> objects, bool transparent = false) {
    raster::Scene scene{raster::OrthoCamera(kSize, kSize), {0, 0, 0}, {}, {}, {}};
    scene.objects = std::move(objects);
    scene.keep_depth = transparent;
    return scene;
}

struct Drawn {
    Framebuffer image{kSize, kSize};
    std::vector<std::uint8_t> alpha;
};

Drawn drawn(const raster::Scene& scene, int samples = 1, int threads = 1, bool every_sample = false) {
    Drawn out;
    raster::Renderer renderer({.threads = threads, .samples = samples, .shade_every_sample = every_sample});
    renderer.render(out.image, scene);
    out.alpha = renderer.coverage();
    return out;
}

std::vector<std::string> rows_of(const Framebuffer& image) {
    std::vector<std::string> rows;
    for (int y = 0; y < image.height(); ++y) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb c = image.pixel(x, y);
            row += std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + " ";
        }
        rows.push_back(row);
    }
    return rows;
}

raster::Rgb bytes_of(float r, float g, float b) {
    return {raster::srgb_byte_from_linear(r), raster::srgb_byte_from_linear(g), raster::srgb_byte_from_linear(b)};
}

void expect_everywhere(const Framebuffer& image, raster::Rgb expected) {
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const raster::Rgb c = image.pixel(x, y);
            ASSERT_EQ(c.r, expected.r) << x << "," << y;
            ASSERT_EQ(c.g, expected.g) << x << "," << y;
            ASSERT_EQ(c.b, expected.b) << x << "," << y;
        }
    }
}

const LinearRgb kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1}, kWhite{1, 1, 1};

}  // namespace

TEST(Transparency, BlendsInLinearLightBackToFrontAsComputedByHand) {
    // Blue at 0.5 over black, green at 0.5 over that, red at 0.5 nearest: premultiplied in linear light.
    const std::vector<raster::SceneObject> layers = {square(0, kRed, blend(0.5F)), square(1, kGreen, blend(0.5F)),
                                                     square(2, kBlue, blend(0.5F))};
    expect_everywhere(drawn(scene_of(layers)).image, bytes_of(0.5F, 0.25F, 0.125F));
    // Two layers: red 0.25 over green 0.75.
    expect_everywhere(drawn(scene_of({square(0, kRed, blend(0.25F)), square(1, kGreen, blend(0.75F))})).image,
                      bytes_of(0.25F, 0.5625F, 0.0F));
}

TEST(Transparency, OpaqueSurfacesHideWhatIsBehindThemWhateverTheirOrder) {
    // Blue behind an opaque white square does not show; red in front is composited over the white.
    const std::vector<raster::SceneObject> objects = {square(2, kBlue, blend(0.5F)), square(0, kRed, blend(0.5F)),
                                                      square(1, kWhite, {})};
    for (int samples : {1, 4}) {
        expect_everywhere(drawn(scene_of(objects), samples).image, bytes_of(1.0F, 0.5F, 0.5F));
        expect_everywhere(drawn(scene_of({objects[2], objects[0], objects[1]}), samples).image,
                          bytes_of(1.0F, 0.5F, 0.5F));
    }
}

TEST(Transparency, EveryFileOrderEverySampleCountAndThreadCountGiveOnePicture) {
    // Three overlapping squares that do not fill the view, so that their edges are sampled too.
    std::array<raster::SceneObject, 3> layers = {square(0, kRed, blend(0.5F), 0.55F, {-0.2F, 0.1F}),
                                                 square(1, kGreen, blend(0.6F), 0.6F, {0.15F, -0.1F}),
                                                 square(2, kBlue, blend(0.7F), 0.5F, {0.1F, 0.25F})};
    for (const int samples : raster::kSampleCounts) {
        std::array<int, 3> order = {0, 1, 2};
        const Drawn first = drawn(scene_of({layers[0], layers[1], layers[2]}), samples);
        do {
            for (const int threads : {1, 3}) {
                const Drawn other = drawn(
                    scene_of({layers[static_cast<std::size_t>(order[0])], layers[static_cast<std::size_t>(order[1])],
                              layers[static_cast<std::size_t>(order[2])]}),
                    samples, threads);
                EXPECT_EQ(rows_of(other.image), rows_of(first.image))
                    << samples << " samples, " << threads << " threads, order " << order[0] << order[1] << order[2];
            }
        } while (std::next_permutation(order.begin(), order.end()));
    }
}

TEST(Transparency, ARendererKeepsNoFragmentsFromOneFrameToTheNext) {
    // A Renderer keeps its fragments' memory: each frame must still draw as a fresh Renderer's first frame.
    const raster::Scene three = scene_of({square(0, kRed, blend(0.5F), 0.55F, {-0.2F, 0.1F}),
                                          square(1, kGreen, blend(0.6F), 0.6F, {0.15F, -0.1F}),
                                          square(2, kBlue, blend(0.7F), 0.5F, {0.1F, 0.25F})});
    const raster::Scene one = scene_of({square(1, kGreen, blend(0.5F), 0.3F, {0.4F, 0.4F})});
    for (const int samples : {1, 4}) {
        raster::Renderer renderer({.samples = samples});
        for (const raster::Scene* scene : {&three, &one, &three, &one}) {
            Framebuffer image(kSize, kSize);
            renderer.render(image, *scene);
            EXPECT_EQ(rows_of(image), rows_of(drawn(*scene, samples).image)) << samples << " samples";
        }
    }
}

TEST(Transparency, TransparentBackgroundTakesAlphaFromEveryLayer) {
    // Red 0.5 over blue 0.5 over nothing: alpha 1 - 0.5 x 0.5, colour the surfaces' alone.
    const std::vector<raster::SceneObject> layers = {square(0, kRed, blend(0.5F)), square(2, kBlue, blend(0.5F))};
    for (const int samples : {1, 4}) {
        for (const bool every_sample : {false, true}) {
            const Drawn out = drawn(scene_of(layers, true), samples, 2, every_sample);
            ASSERT_EQ(out.alpha.size(), static_cast<std::size_t>(kSize * kSize));
            for (const std::uint8_t a : out.alpha) ASSERT_EQ(a, 191) << samples << " samples";
            expect_everywhere(out.image, bytes_of(0.5F / 0.75F, 0.0F, 0.25F / 0.75F));
        }
    }
    // Over an opaque surface the alpha is whole again.
    const Drawn over = drawn(scene_of({layers[0], square(3, kWhite, {})}, true));
    for (const std::uint8_t a : over.alpha) ASSERT_EQ(a, 255);
}

TEST(Transparency, PartlyCoveredPixelsOfATransparentBackgroundShareTheirAlpha) {
    // A half-transparent square whose edges cross pixels: alpha is its coverage times one half.
    const raster::Scene scene = scene_of({square(0, kRed, blend(0.5F), 0.5F, {0.05F, 0.0F})}, true);
    const Drawn out = drawn(scene, 16);
    int partial = 0;
    for (const std::uint8_t a : out.alpha) {
        EXPECT_LE(a, 128);
        partial += a > 0 && a < 127 ? 1 : 0;
    }
    EXPECT_GT(partial, 0);  // the edges fall between pixels
}

TEST(Transparency, MaskShowsASurfaceWholeWhenItsAlphaReachesTheCutoff) {
    const raster::Opacity kept{raster::AlphaMode::mask, 0.5F, 0.5F}, cut{raster::AlphaMode::mask, 0.4F, 0.5F};
    expect_everywhere(drawn(scene_of({square(0, kRed, kept), square(1, kBlue, {})})).image, bytes_of(1, 0, 0));
    expect_everywhere(drawn(scene_of({square(0, kRed, cut), square(1, kBlue, {})})).image, bytes_of(0, 0, 1));
}

TEST(Transparency, MaskedEdgesAreAntiAliasedByTheSamples) {
    // The left texel opaque, the right cut: the cut runs down the centre of column 4 (x = 0).
    raster::SceneObject cut = square(0, kWhite, {raster::AlphaMode::mask, 1.0F, 0.5F});
    cut.texture = std::make_shared<const raster::Texture>(Framebuffer(2, 1, std::vector<std::uint8_t>(6, 255)),
                                                          std::vector<std::uint8_t>{255, 0});
    cut.sampler = {raster::TextureFilter::nearest, raster::TextureWrap::clamp};
    const auto shares = [](const Framebuffer& image) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) {
            const double share = raster::linear_from_srgb_channel(image.pixel(x, 4).g / 255.0);
            row += share > 0.99 ? '#' : share < 0.01 ? '.' : std::abs(share - 0.5) < 0.01 ? 'o' : '?';
        }
        return row;
    };
    EXPECT_EQ(shares(drawn(scene_of({cut, square(1, {0, 0, 0}, {})})).image), "####.....");
    EXPECT_EQ(shares(drawn(scene_of({cut, square(1, {0, 0, 0}, {})}), 4).image), "####o....");
    EXPECT_EQ(shares(drawn(scene_of({cut, square(1, {0, 0, 0}, {})}), 16).image), "####o....");
}

TEST(Transparency, TextureAlphaMultipliesTheBlendFactor) {
    raster::SceneObject glass = square(0, kWhite, blend(0.5F));
    glass.texture = std::make_shared<const raster::Texture>(Framebuffer(1, 1, std::vector<std::uint8_t>(3, 255)),
                                                            std::vector<std::uint8_t>{51});
    expect_everywhere(drawn(scene_of({glass})).image, bytes_of(0.1F, 0.1F, 0.1F));
}

TEST(Transparency, OpaqueScenesDrawAsBefore) {
    // An object whose alpha is not blended draws the same whatever its factor says.
    raster::Opacity ignored{raster::AlphaMode::opaque, 0.25F, 0.5F};
    expect_everywhere(drawn(scene_of({square(0, kRed, ignored), square(1, kBlue, {})})).image, bytes_of(1, 0, 0));
}
