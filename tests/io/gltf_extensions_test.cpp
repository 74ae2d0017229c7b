// glTF's material extensions and cameras, read from the file's JSON, on the shared written square.
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>

#include "io/model_wire.hpp"
#include "support/gltf_square.hpp"
#include "support/scratch.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <gtest/gtest.h>

using raster::Model;
using test_support::ScratchDir;

namespace {

// The shared square with its red and blue strip as texture 0, drawn with `material` (JSON) by
// `nodes` (node 0 holds the mesh).
std::filesystem::path write_square(const std::filesystem::path& dir, const std::string& material,
                                   const std::string& extras = "", const std::string& nodes = R"([{"mesh": 0}])") {
    return test_support::write_gltf_square(dir, material, extras, nodes, true);
}

// A matte base colour map, moved by `transform` (JSON of KHR_texture_transform, or "").
std::string mapped_material(const std::string& transform) {
    const std::string moved =
        transform.empty() ? "" : R"(, "extensions": {"KHR_texture_transform": )" + transform + "}";
    return R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0)" + moved +
           R"(}, "metallicFactor": 0, "roughnessFactor": 1}})";
}

const std::string kUsesTransform = R"( "extensionsUsed": ["KHR_texture_transform"],)";

// The model seen square on from +z, filling the picture (or through its camera `camera`):
// `columns` pixels wide, one row read.
std::vector<raster::Rgb> middle_row(const Model& model, int columns = 8, int camera = -1) {
    raster::ModelView view;
    view.eye = glm::dvec3(0.0, 0.0, 4.0);
    view.target = glm::dvec3(0.0);
    view.orthographic = true;
    view.half_height = 0.9;  // no pixel centre on the square's edges
    if (camera >= 0) view = raster::through_camera(view, model.cameras.at(static_cast<std::size_t>(camera)), model);
    raster::Framebuffer image(columns, columns);
    raster::DepthBuffer depth;
    raster::ModelStage(std::make_shared<const Model>(model), view, columns, columns)
        .render(image, depth, 0.0, {.samples = 1});
    std::vector<raster::Rgb> row;
    for (int x = 0; x < columns; ++x) row.push_back(image.pixel(x, columns / 2));
    return row;
}

// 'r' where red leads, 'b' where blue does, '.' otherwise, left to right.
std::string hues(const std::vector<raster::Rgb>& row) {
    std::string out;
    for (const raster::Rgb& c : row) out += c.r > c.b + 20 ? 'r' : c.b > c.r + 20 ? 'b' : '.';
    return out;
}

}  // namespace

TEST(GltfTextureTransform, IdentityDrawsTheMapWhereItLies) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), mapped_material("")));
    ASSERT_TRUE(model.parts[0].metallic_roughness.has_value());
    EXPECT_TRUE(model.parts[0].metallic_roughness->base_colour_transform.identity());
    EXPECT_EQ(hues(middle_row(model)), "rrrrbbbb");
}

TEST(GltfTextureTransform, OffsetShiftsTheBaseColourMap) {
    const ScratchDir dir;
    const Model model =
        raster::read_model(write_square(dir.path(), mapped_material(R"({"offset": [0.5, 0]})"), kUsesTransform));
    ASSERT_TRUE(model.parts[0].metallic_roughness.has_value());
    EXPECT_EQ(model.parts[0].metallic_roughness->base_colour_transform.offset, glm::vec2(0.5F, 0.0F));
    for (const std::string& warning : model.warnings)
        EXPECT_EQ(warning.find("KHR_texture_transform"), std::string::npos) << warning;
    EXPECT_EQ(hues(middle_row(model)), "bbbbrrrr");
}

TEST(GltfTextureTransform, ScaleRepeatsTheMap) {
    const ScratchDir dir;
    const Model model =
        raster::read_model(write_square(dir.path(), mapped_material(R"({"scale": [2, 1]})"), kUsesTransform));
    EXPECT_EQ(hues(middle_row(model)), "rrbbrrbb");
}

// The specification's example: a quarter turn about glTF's origin (the image's top left).
TEST(GltfTextureTransform, RotationTurnsAboutTheImagesTopLeft) {
    const raster::TextureTransform quarter{{0.0F, 0.0F}, std::numbers::pi_v<float> / 2.0F, {1.0F, 1.0F}};
    // glTF (u, v) = (0.25, 0.5) turns to (v, -u) = (0.5, -0.25); raster's v runs up: 1 - v.
    const raster::MovedUv at = raster::moved_uv(quarter, {0.25F, 0.5F}, {{1.0F, 0.0F}, {0.0F, 1.0F}});
    EXPECT_NEAR(at.uv.x, 0.5F, 1e-6F);
    EXPECT_NEAR(at.uv.y, 1.25F, 1e-6F);
    // A step right in u becomes a step in -v of glTF's frame, up in raster's.
    EXPECT_NEAR(at.footprint.per_pixel_x.x, 0.0F, 1e-6F);
    EXPECT_NEAR(at.footprint.per_pixel_x.y, 1.0F, 1e-6F);
    const raster::MovedUv same = raster::moved_uv({}, {0.3F, 0.7F}, {{0.1F, 0.2F}, {0.3F, 0.4F}});
    EXPECT_EQ(same.uv, glm::vec2(0.3F, 0.7F));  // bit for bit: the identity moves nothing
}

TEST(GltfTextureTransform, EveryMapCarriesItsOwnAndTravelsToTheRenderer) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), R"({"name": "moved",
      "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.25]}}},
                               "metallicRoughnessTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 3]}}}},
      "normalTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"rotation": 0.5}}},
      "occlusionTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"offset": [0, 1]}}},
      "emissiveTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [4, 4], "rotation": 1}}}})",
                                                        kUsesTransform));
    ASSERT_TRUE(model.parts[0].metallic_roughness.has_value());
    std::vector<std::uint8_t> wire;
    raster::detail::append_model_wire(model, wire);
    const Model carried = raster::detail::model_from_wire(wire);
    ASSERT_TRUE(carried.parts[0].metallic_roughness.has_value());
    for (const Model* m : {&model, &carried}) {
        const raster::MetallicRoughness& p = *m->parts[0].metallic_roughness;
        EXPECT_EQ(p.base_colour_transform.offset, glm::vec2(0.5F, 0.25F));
        EXPECT_EQ(p.metallic_roughness_transform.scale, glm::vec2(2.0F, 3.0F));
        EXPECT_EQ(p.normal_transform.rotation, 0.5F);
        EXPECT_EQ(p.occlusion_transform.offset, glm::vec2(0.0F, 1.0F));
        EXPECT_EQ(p.emissive_transform, (raster::TextureTransform{{0.0F, 0.0F}, 1.0F, {4.0F, 4.0F}}));
    }
}

TEST(GltfTextureTransform, AnotherCoordinateSetWarnsAndReadsTheFirst) {
    const ScratchDir dir;
    const Model model = raster::read_model(
        write_square(dir.path(), mapped_material(R"({"offset": [0.5, 0], "texCoord": 1})"), kUsesTransform));
    ASSERT_EQ(model.warnings.size(), 1U);
    EXPECT_NE(model.warnings[0].find("coordinate set 1"), std::string::npos) << model.warnings[0];
    EXPECT_EQ(hues(middle_row(model)), "bbbbrrrr");
}

TEST(GltfTextureTransform, FieldThatIsNoNumberWarnsAndIsLeftOut) {
    const ScratchDir dir;
    const Model model = raster::read_model(
        write_square(dir.path(), mapped_material(R"({"offset": [0.5, 0, 1], "rotation": "half", "scale": [2, 1]})"),
                     kUsesTransform));
    ASSERT_EQ(model.warnings.size(), 2U);
    EXPECT_NE(model.warnings[0].find("offset is not two numbers"), std::string::npos) << model.warnings[0];
    EXPECT_NE(model.warnings[1].find("rotation is not a number"), std::string::npos) << model.warnings[1];
    EXPECT_EQ(model.parts[0].metallic_roughness->base_colour_transform,
              (raster::TextureTransform{{0.0F, 0.0F}, 0.0F, {2.0F, 1.0F}}));
}

// assimp 5.2.5's parser aborts on them: refused in raster's words before it reads the file.
TEST(GltfTextureTransform, PairOfFewerThanTwoNumbersIsRefusedInOneLine) {
    const ScratchDir dir;
    for (const char* pair : {R"({"offset": [0.5]})", R"({"scale": [2, "x"]})"}) {
        try {
            (void)raster::read_model(write_square(dir.path(), mapped_material(pair), kUsesTransform));
            ADD_FAILURE() << pair << " was read";
        } catch (const std::runtime_error& refusal) {
            EXPECT_NE(std::string(refusal.what()).find("material 0's base colour map's KHR_texture_transform"),
                      std::string::npos)
                << refusal.what();
            EXPECT_NE(std::string(refusal.what()).find("is not a pair of numbers"), std::string::npos)
                << refusal.what();
        }
    }
}

TEST(GltfEmissiveStrength, ScalesTheEmissiveFactor) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), R"({"emissiveFactor": [0, 0.25, 0],
      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}})",
                                                        R"( "extensionsUsed": ["KHR_materials_emissive_strength"],)"));
    ASSERT_TRUE(model.parts[0].metallic_roughness.has_value());
    EXPECT_EQ(model.parts[0].metallic_roughness->emissive.g, 1.0F);
    EXPECT_TRUE(model.warnings.empty()) << model.warnings[0];
}

TEST(GltfEmissiveStrength, NegativeWarnsAndDrawsAsOne) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), R"({"emissiveFactor": [0, 0.25, 0],
      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": -2}}})"));
    EXPECT_EQ(model.parts[0].metallic_roughness->emissive.g, 0.25F);
    ASSERT_EQ(model.warnings.size(), 1U);
    EXPECT_NE(model.warnings[0].find("emissiveStrength -2"), std::string::npos) << model.warnings[0];
}

// Seen from 4 in front and from 4 behind (turned half about y), each framing the square as
// middle_row does: from behind, +x is on the left.
const std::string kTwoCameras = R"( "cameras": [
    {"type": "perspective", "perspective": {"yfov": 0.4427, "znear": 0.1, "zfar": 100}},
    {"type": "perspective", "name": "back", "perspective": {"yfov": 0.4427, "znear": 0.1}}],)";
const std::string kCameraNodes = R"([{"mesh": 0, "children": [1, 2]}, {"camera": 0, "translation": [0, 0, 4]},
    {"camera": 1, "translation": [0, 0, -4], "rotation": [0, 1, 0, 0]}])";

TEST(RenderCamera, UsesTheFilesCamera) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), mapped_material(""), kTwoCameras, kCameraNodes));
    ASSERT_EQ(model.cameras.size(), 2U);
    EXPECT_NEAR(model.cameras[0].yfov_degrees, 0.4427 * 180.0 / std::numbers::pi, 1e-9);
    EXPECT_EQ(model.cameras[0].far, 100.0);
    EXPECT_EQ(model.cameras[1].name, "back");
    EXPECT_NEAR(model.cameras[1].forward.z, 1.0, 1e-12);  // its -Z turned to +Z
    EXPECT_NEAR(model.cameras[1].eye.z, -4.0, 1e-12);
    EXPECT_EQ(hues(middle_row(model, 8, 0)), "rrrrbbbb");
    EXPECT_EQ(hues(middle_row(model, 8, 1)), "bbbbrrrr");
    // Carried by the reader process; the cameras are not "dropped": no warning names them.
    std::vector<std::uint8_t> wire;
    raster::detail::append_model_wire(model, wire);
    const Model carried = raster::detail::model_from_wire(wire);
    ASSERT_EQ(carried.cameras.size(), 2U);
    EXPECT_EQ(carried.cameras[1].eye, model.cameras[1].eye);
    EXPECT_EQ(carried.cameras[0].far, 100.0);
    EXPECT_FALSE(carried.cameras[1].far.has_value());
    for (const std::string& warning : model.warnings) EXPECT_EQ(warning.find("camera"), std::string::npos) << warning;
}

TEST(RenderCamera, OrthographicTakesItsHeightFromYmag) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(
        dir.path(), mapped_material(""),
        R"( "cameras": [{"type": "orthographic", "orthographic": {"xmag": 1.8, "ymag": 1.8, "znear": 0, "zfar": 9}}],)",
        R"([{"mesh": 0, "children": [1]}, {"camera": 0, "translation": [0.9, 0, 4]}])"));
    ASSERT_EQ(model.cameras.size(), 1U);
    EXPECT_TRUE(model.cameras[0].orthographic);
    // Twice as high as middle_row's and moved right by half its width: the square fills the left half.
    EXPECT_EQ(hues(middle_row(model, 8, 0)), "rrbb....");
}

TEST(RenderCamera, OutOfRangeSaysHowManyThereAre) {
    const ScratchDir dir;
    const Model model = raster::read_model(write_square(dir.path(), mapped_material(""), kTwoCameras, kCameraNodes));
    EXPECT_EQ(raster::camera_refusal(model, 2), "--camera 2: the model carries 2 cameras (--camera 0 to 1)");
    const Model without = raster::read_model(write_square(dir.path(), mapped_material("")));
    EXPECT_EQ(raster::camera_refusal(without, 0), "--camera 0: the model carries no cameras");
}

TEST(RenderCamera, AimsAtThePointAheadNearestTheModelsCentreInTheFilesCoordinates) {
    const ScratchDir dir;
    // The square 10 ahead of a camera at the origin looking down the file's -Z.
    const Model model = raster::read_model(
        write_square(dir.path(), mapped_material(""),
                     R"( "cameras": [{"type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}}],)",
                     R"([{"children": [1, 2]}, {"mesh": 0, "translation": [0, 0, -10]}, {"camera": 0}])"));
    ASSERT_EQ(model.cameras.size(), 1U);
    const raster::ModelView view = raster::through_camera({}, model.cameras[0], model);
    ASSERT_TRUE(view.target.has_value());
    EXPECT_NEAR(view.target->z, -10.0, 1e-6);
    EXPECT_NEAR(view.target->x, 0.0, 1e-6);
}
