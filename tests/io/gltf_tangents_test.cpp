// glTF's TANGENT attribute (doc/conventions.md#normal-maps): read through assimp, moved by the
// node's matrix and mirrored into raster's world with its handedness, and kept only where a
// normal map needs it.
#include <raster/geometry/tangents.hpp>
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>

#include "support/model_files.hpp"
#include "support/scratch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using raster::Model;
using test_support::ScratchDir;

namespace {

// A square in the file's z = 0 plane facing +z, u along +x and the image's top at +y, with
// NORMAL, TEXCOORD_0 and TANGENT `tangent` (none when w is 0), placed by `node` (JSON), its
// material `material`; the buffer in tangents.bin beside it, and stripes.png: stripes two texels
// wide whose normals lean toward -u and +u in turn.
std::filesystem::path write_square(const std::filesystem::path& dir, glm::vec4 tangent, const std::string& node,
                                   const std::string& material) {
    std::string buffer;
    const auto put = [&](float v) { buffer.append(reinterpret_cast<const char*>(&v), sizeof v); };
    for (const float v : {-1.0F, -1.0F, 0.0F, 1.0F, -1.0F, 0.0F, 1.0F, 1.0F, 0.0F, -1.0F, 1.0F, 0.0F}) put(v);
    for (int i = 0; i < 4; ++i) put(0.0F), put(0.0F), put(1.0F);
    for (const float v : {0.0F, 1.0F, 1.0F, 1.0F, 1.0F, 0.0F, 0.0F, 0.0F}) put(v);  // glTF's v runs down
    for (int i = 0; i < 4; ++i) put(tangent.x), put(tangent.y), put(tangent.z), put(tangent.w);
    for (const int i : {0, 1, 2, 0, 2, 3}) {
        const auto index = static_cast<std::uint16_t>(i);
        buffer.append(reinterpret_cast<const char*>(&index), sizeof index);
    }
    std::ofstream(dir / "tangents.bin", std::ios::binary) << buffer;
    std::vector<std::uint8_t> texels;
    for (int texel = 0; texel < 8 * 8; ++texel)
        texels.insert(texels.end(), {static_cast<std::uint8_t>((texel % 8) / 2 % 2 == 0 ? 64 : 191), 128, 238});
    test_support::write_png(dir / "stripes.png", raster::Framebuffer(8, 8, std::move(texels)));
    const std::string attribute = tangent.w != 0.0F ? R"(, "TANGENT": 3)" : "";
    test_support::write_text(dir / "tangents.gltf", R"({"asset": {"version": "2.0"}, "scene": 0,
  "scenes": [{"nodes": [0]}], "nodes": [)" + node + R"(],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2)" +
                                                        attribute + R"(},
                              "indices": 4, "material": 0}]}],
  "materials": [)" + material + R"(], "images": [{"uri": "stripes.png"}], "textures": [{"source": 0}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC4"},
                {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                  {"buffer": 0, "byteOffset": 96, "byteLength": 32}, {"buffer": 0, "byteOffset": 128, "byteLength": 64},
                  {"buffer": 0, "byteOffset": 192, "byteLength": 12}],
  "buffers": [{"byteLength": 204, "uri": "tangents.bin"}]})");
    return dir / "tangents.gltf";
}

constexpr const char* kNormalMapped =
    R"({"pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0.5}, "normalTexture": {"index": 0}})";

void expect_near(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(glm::distance(actual, expected), 0.0F, 1e-5F) << actual.x << ' ' << actual.y << ' ' << actual.z;
}

raster::Framebuffer drawn(const Model& model) {
    raster::Framebuffer image(64, 64);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const Model>(model), {}, image.width(), image.height())
        .render(image, depth, 0.0, {.samples = 1});
    return image;
}

// The largest difference of any channel between two pictures of one size.
int largest_difference(const raster::Framebuffer& a, const raster::Framebuffer& b) {
    int largest = 0;
    for (std::size_t i = 0; i < a.bytes().size(); ++i)
        largest = std::max(largest, std::abs(a.bytes()[i] - b.bytes()[i]));
    return largest;
}

}  // namespace

// The file's tangent (1, 0, 0) with w = 1 is right-handed: n x t is +y, where the image's top is.
// Mirrored into raster's left-handed world (z turned round) the tangent keeps its direction and w
// turns to -1, so that w (n x t) is still +y; a node that mirrors x turns it back. In each case
// the tangents are those tangents_from_uvs makes from the same square, and the file's w = -1
// arrives turned too.
TEST(GltfTangents, AreReadFromTheFile) {
    struct Case {
        const char* node;
        float w;
        glm::vec3 tangent;
        float read_w;
    };
    for (const Case& c : {Case{R"({"mesh": 0})", 1.0F, {1, 0, 0}, -1.0F},
                          Case{R"({"mesh": 0, "scale": [-1, 1, 1]})", 1.0F, {-1, 0, 0}, 1.0F},
                          Case{R"({"mesh": 0, "rotation": [0, 0, 0.7071068, 0.7071068]})", 1.0F, {0, 1, 0}, -1.0F},
                          Case{R"({"mesh": 0})", -1.0F, {1, 0, 0}, 1.0F}}) {
        SCOPED_TRACE(std::string(c.node) + " w " + std::to_string(c.w));
        const ScratchDir dir;
        const Model model = raster::read_model(write_square(dir.path(), {1, 0, 0, c.w}, c.node, kNormalMapped));
        ASSERT_EQ(model.parts.size(), 1U);
        const raster::Mesh& mesh = model.parts[0].mesh;
        ASSERT_EQ(mesh.tangents.size(), mesh.positions.size());
        const std::vector<glm::vec4> made = raster::tangents_from_uvs(mesh);
        for (std::size_t i = 0; i < mesh.tangents.size(); ++i) {
            expect_near(glm::vec3(mesh.tangents[i]), c.tangent);
            EXPECT_EQ(mesh.tangents[i].w, c.read_w);
            if (c.w > 0.0F) {  // the file's w = -1 says the texture is mirrored, which these coordinates are not
                expect_near(glm::vec3(made[i]), glm::vec3(mesh.tangents[i]));
                EXPECT_EQ(made[i].w, mesh.tangents[i].w);
            }
        }
    }
}

// Tangents serve the normal map alone: a material without one does not carry them.
TEST(GltfTangents, AreLeftOutWhereNoNormalMapNeedsThem) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), {1, 0, 0, 1}, R"({"mesh": 0})", "{}"));
    ASSERT_EQ(model.parts.size(), 1U);
    EXPECT_TRUE(model.parts[0].mesh.tangents.empty());
    EXPECT_FALSE(model.parts[0].mesh.uvs.empty());
}

// A model without TANGENT gets tangents made from its texture coordinates when it is staged, and
// draws as the file's own (1, 0, 0, 1) do; the file's tangents turned a quarter draw otherwise.
TEST(GltfTangents, MadeOnesDrawAsTheFilesAndTurnedOnesDrawOtherwise) {
    const ScratchDir dir;
    const auto picture = [&](glm::vec4 tangent) {
        return drawn(raster::read_model(write_square(dir.path(), tangent, R"({"mesh": 0})", kNormalMapped)));
    };
    const raster::Framebuffer file = picture({1, 0, 0, 1});
    EXPECT_LE(largest_difference(picture({0, 0, 0, 0}), file), 2);
    EXPECT_GE(largest_difference(picture({0, 1, 0, 1}), file), 20);
}
