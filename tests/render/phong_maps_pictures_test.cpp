// A classic MTL material's specular, glow and bump maps drawn, read from files written here and
// compared with snapshots/mtl/ (doc/conventions.md#mtl-maps).
#include <raster/io/obj_file.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include "support/golden.hpp"
#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>
#include <gtest/gtest.h>

namespace {

// A 32 x 32 image whose texel (x, y) is `texel(x, y)`, row 0 at the top.
template <typename Texel>
raster::Framebuffer image_of(Texel texel) {
    std::vector<std::uint8_t> bytes;
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const raster::Rgb c = texel(x, y);
            bytes.insert(bytes.end(), {c.r, c.g, c.b});
        }
    }
    return raster::Framebuffer(32, 32, std::move(bytes));
}

}  // namespace

// Ridges across the square from its bump map catch the light from the upper left; the
// highlight shows only on the left half, where the specular map is white; a green ring glows
// where the glow map is, the rest of Ke 0 0.9 0 left dark by the map.
TEST(Golden, MtlSpecularGlowAndBumpMapsOnASquare) {
    const test_support::ScratchDir dir;
    test_support::write_png(dir / "spec.png", image_of([](int x, int) {
                                return x < 16 ? raster::Rgb{255, 255, 255} : raster::Rgb{0, 0, 0};
                            }));
    test_support::write_png(dir / "glow.png", image_of([](int x, int y) {
                                const double r = std::hypot(x - 15.5, y - 15.5);
                                return r > 9 && r < 12 ? raster::Rgb{255, 255, 255} : raster::Rgb{0, 0, 0};
                            }));
    test_support::write_png(dir / "ridges.png", image_of([](int, int y) {
                                const auto h = static_cast<std::uint8_t>(127.5 + 127.5 * std::sin(y * 0.785398));
                                return raster::Rgb{h, h, h};
                            }));
    test_support::write_text(dir / "sq.mtl", "newmtl sq\nKd 0.5 0.5 0.5\nKs 0.6 0.6 0.6\nNs 24\nKe 0 0.9 0\n"
                                             "map_Ks spec.png\nmap_Ke glow.png\nbump -bm 0.8 ridges.png\n");
    test_support::write_text(dir / "sq.obj", "mtllib sq.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\nusemtl sq\n"
                                             "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
    const raster::Model model = raster::read_obj(dir / "sq.obj");
    ASSERT_EQ(model.parts.size(), 1U);
    ASSERT_TRUE(model.warnings.empty()) << model.warnings.front();
    const raster::ModelPart& part = model.parts[0];
    raster::PerspectiveScene scene{
        raster::PerspectiveCamera::look_at(96, 96, {0, 0, -4.5}, {0, 0, 0}, {0, 1, 0}, {30.0, 0.1, 100.0}),
        {0, 0, 0},
        {{{-1.0F, 1.0F, -1.5F}, 1.0F}},
        {},
        {}};
    scene.objects.push_back({std::make_shared<const raster::Mesh>(part.mesh), glm::mat4(1.0F), part.material,
                             raster::ShadingMethod::phong, std::nullopt, part.texture, part.sampler, part.opacity,
                             part.phong_maps});
    raster::Framebuffer image(96, 96);
    raster::DepthBuffer depth;
    raster::render(image, scene, depth, {.samples = raster::kSmoothSamples});
    EXPECT_TRUE(test_support::matches_snapshot(image, "mtl/specular-glow-bump-square"));
}
