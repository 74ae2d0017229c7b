// Open surfaces (a lone triangle, a plane, a leaf) are drawn from both sides; closed ones keep
// culling their back faces, the fast path.
#include <raster/io/obj_file.hpp>
#include <raster/render/model_scene.hpp>

#include "support/model_files.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>
#include <glm/geometric.hpp>

using raster::Framebuffer;
using raster::Model;

namespace {

const raster::Rgb kBackground{48, 52, 60};

// One triangle facing +Z, counter-clockwise as OBJ writes fronts.
const char* const kTriangle = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";

// The picture from an eye on the z axis at `z`, lit from the eye, flat and small.
Framebuffer seen_from(double z, raster::Culling cull) {
    raster::ModelView view;
    view.eye = glm::dvec3(0.0, 0.0, z);
    view.light = glm::dvec3(0.0, 0.0, z);
    view.shading = raster::ShadingMethod::flat;
    view.cull = cull;
    Framebuffer image(24, 24);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const Model>(raster::parse_obj(kTriangle, "")), view, 24, 24)
        .render(image, depth);
    return image;
}

int covered(const Framebuffer& image) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) count += image.pixel(x, y) != kBackground ? 1 : 0;
    }
    return count;
}

}  // namespace

TEST(OpenSurfaces, ALoneTriangleIsSeenAndLitFromBothSides) {
    const Framebuffer front = seen_from(5.0, raster::Culling::automatic);
    const Framebuffer back = seen_from(-5.0, raster::Culling::automatic);
    EXPECT_GT(covered(front), 50);
    // From behind the same area shows, mirrored, and lit as brightly: its normal is turned too.
    EXPECT_EQ(covered(back), covered(front));
    EXPECT_EQ(back.pixel(12, 14), front.pixel(12, 14));
    EXPECT_NE(front.pixel(12, 14), kBackground);
    // Culling asked for: from behind, nothing.
    EXPECT_EQ(covered(seen_from(-5.0, raster::Culling::back)), 0);
    EXPECT_EQ(covered(seen_from(5.0, raster::Culling::back)), covered(front));
}

TEST(OpenSurfaces, OnlyPartsWithAnEdgeLeftOpenAreDrawnFromBothSides) {
    // The crate test model: a closed cube standing on an open floor quad.
    const Model crate =
        raster::parse_obj(test_support::textured_cube_obj("lib.mtl", "crate") +
                              "v -3 -1 -3\nv 3 -1 -3\nv 3 -1 3\nv -3 -1 3\nusemtl floor\nf 9 10 11 12\n",
                          "newmtl crate\nKd 1 0 0\nnewmtl floor\nKd 0 1 0\n");
    ASSERT_EQ(crate.parts.size(), 2U);
    EXPECT_EQ(raster::open_parts(crate), (std::vector<bool>{false, true}));
    // A closed cube split between two materials is still closed: its seams meet across the parts.
    const std::string cube = test_support::textured_cube_obj("", "");
    std::string split = "mtllib lib.mtl\n";
    int face = 0;
    for (std::size_t start = 0; start < cube.size();) {
        const std::size_t end = cube.find('\n', start);
        const std::string line = cube.substr(start, end - start);
        if (line.rfind("f ", 0) == 0 && face++ % 2 == 0)
            split += "usemtl a\n" + line + "\nusemtl b\n";
        else
            split += line + "\n";
        start = end + 1;
    }
    const Model two_parts = raster::parse_obj(split, "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 0 1\n");
    ASSERT_EQ(two_parts.parts.size(), 2U);
    EXPECT_EQ(raster::open_parts(two_parts), (std::vector<bool>{false, false}));
    // A face wound the wrong way leaves its edges running one way twice: open, so it shows.
    const Model flipped =
        raster::parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nf 1 2 3\n", "");
    EXPECT_EQ(raster::open_parts(flipped), (std::vector<bool>{true}));
}

TEST(OpenSurfaces, BothSidesDoublesTheFacetsWithTurnedNormals) {
    const Model model = raster::parse_obj(kTriangle, "");
    const raster::Mesh& mesh = model.parts.at(0).mesh;
    const raster::Mesh doubled = raster::both_sides(mesh);
    ASSERT_EQ(doubled.facets.size(), 2 * mesh.facets.size());
    ASSERT_EQ(doubled.positions.size(), 2 * mesh.positions.size());
    const raster::Facet& turned = doubled.facets.back();
    EXPECT_EQ(turned.normal, -mesh.facets[0].normal);
    const glm::vec3 a = doubled.positions[turned.corners[0]], b = doubled.positions[turned.corners[1]],
                    c = doubled.positions[turned.corners[2]];
    EXPECT_EQ(raster::facet_normal(a, b, c), turned.normal);  // clockwise from its own side
    EXPECT_EQ(doubled.normals[turned.corners[0]], -mesh.normals[mesh.facets[0].corners[0]]);
}

// The back copy's whole tangent frame turns round with its normal (w too, since n x t does not),
// so a normal map's normal there is the front's turned round, as glTF's double-sided back faces.
TEST(OpenSurfaces, BothSidesTurnsTheBackCopysTangentFrameRound) {
    raster::Mesh mesh = raster::parse_obj(kTriangle, "").parts.at(0).mesh;
    mesh.tangents.assign(mesh.positions.size(), glm::vec4(1, 0, 0, -1));
    const raster::Mesh doubled = raster::both_sides(mesh);
    ASSERT_EQ(doubled.tangents.size(), doubled.positions.size());
    const glm::vec3 texel(0.3F, 0.4F, 0.866F);
    const auto mapped = [&](const raster::Mesh& m, std::size_t i) {
        const glm::vec3 n = m.normals[i], t(m.tangents[i]);
        return texel.x * t + texel.y * m.tangents[i].w * glm::cross(n, t) + texel.z * n;
    };
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        EXPECT_EQ(doubled.tangents[i], mesh.tangents[i]);
        EXPECT_EQ(doubled.tangents[i + mesh.positions.size()], -mesh.tangents[i]);
        EXPECT_EQ(mapped(doubled, i + mesh.positions.size()), -mapped(mesh, i));
    }
}

// Both copies keep each vertex's alpha (doc/conventions.md#vertex-alpha).
TEST(OpenSurfaces, BothSidesGivesTheBackCopyTheFrontsVertexAlphas) {
    raster::Mesh mesh = raster::parse_obj(kTriangle, "").parts.at(0).mesh;
    mesh.alphas = {0.25F, 0.5F, 0.75F};
    const raster::Mesh doubled = raster::both_sides(mesh);
    EXPECT_EQ(doubled.alphas, (std::vector<float>{0.25F, 0.5F, 0.75F, 0.25F, 0.5F, 0.75F}));
}
