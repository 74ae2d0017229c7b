// The diary's scenes: one table and the poses it names; stays whole so each reads by its entry.
#include <raster/scenes/diary_scenes.hpp>

#include <raster/geometry/shapes.hpp>
#include <raster/scenes/scenes.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <glm/ext/matrix_transform.hpp>

namespace raster {
namespace {

constexpr std::array<SceneInfo, 15> kScenes{{
    {"lit-cube", "0.0.8", "the tumbling cube lit by one light, flat shaded", 360},
    {"dodecahedron", "0.0.9", "a tumbling dodecahedron, the first triangle mesh", 360},
    {"orbit", "0.0.10", "the camera orbits the dodecahedron, then holds still", 720},
    {"faceted-sphere", "0.0.11", "a flat-shaded octahedron sphere: orbit, then tumble", 720},
    {"smooth-sphere", "0.0.12", "Gouraud shading: orbit, then a vertical squash", 720},
    {"glossy-sphere", "0.0.13", "Blinn-Phong highlights interpolated per vertex", 720},
    {"squash", "0.0.14", "normals by the inverse transpose, a deeper squash", 720},
    {"phong-sphere", "0.0.15", "per-pixel (Phong) normals: a round highlight", 720},
    {"two-spheres", "0.0.16", "two spheres, a depth buffer, one circle of the camera", 720},
    {"torus", "0.0.17", "a Phong-shaded torus(48, 32) tumbling", 360},
    {"materials", "0.1.0", "the torus in linear light, its palette on grey", 360},
    {"three-lights", "0.1.1", "three directional lights summed on the torus", 360},
    {"point-lights", "0.1.6", "one directional and two point lights on the torus", 360},
    {"point-light", "0.1.6", "a point light circling over a ground quad", 360},
    {"shaders", "0.1.7", "Phong (left) against Gouraud (right), side by side", 360},
}};

enum SceneId {
    kLitCube,
    kDodecahedron,
    kOrbit,
    kFacetedSphere,
    kSmoothSphere,
    kGlossySphere,
    kSquash,
    kPhongSphere,
    kTwoSpheres,
    kTorus,
    kMaterials,
    kThreeLights,
    kPointLights,
    kPointLight,
    kShaders
};
// The switches below go by position in kScenes: these keep the two lists in step.
static_assert(kScenes[kLitCube].name == "lit-cube" && kScenes[kDodecahedron].name == "dodecahedron" &&
              kScenes[kOrbit].name == "orbit" && kScenes[kFacetedSphere].name == "faceted-sphere" &&
              kScenes[kSmoothSphere].name == "smooth-sphere" && kScenes[kGlossySphere].name == "glossy-sphere" &&
              kScenes[kSquash].name == "squash" && kScenes[kPhongSphere].name == "phong-sphere" &&
              kScenes[kTwoSpheres].name == "two-spheres" && kScenes[kTorus].name == "torus" &&
              kScenes[kMaterials].name == "materials" && kScenes[kThreeLights].name == "three-lights" &&
              kScenes[kPointLights].name == "point-lights" && kScenes[kPointLight].name == "point-light" &&
              kScenes[kShaders].name == "shaders");
// The scenes of the diary's Phase 2 (0.1.0 on) light in linear colour.
constexpr bool is_phase2(std::ptrdiff_t id) { return id >= kMaterials; }

constexpr Rgb kShapeColour{52, 110, 210};  // #346ED2, the diary's blue
constexpr Rgb kSecondColour{210, 90, 52};  // the smaller sphere of 0.0.16
constexpr Rgb kTerracotta{185, 72, 58};    // the ground of the 0.0.16 still
constexpr glm::vec3 kSunFromRight{1.0F, 1.0F, -1.0F};
constexpr glm::vec3 kLowSun{1.0F, 0.5F, -1.0F};
constexpr glm::vec3 kHighLeftLamp{-10.0F, 10.0F, -10.0F};
constexpr glm::vec3 kStillEye{0.1F, 0.4F, -1.0F};
constexpr float kOrbitHeight = 0.2F;

// Phase 2: the three.js geometry browser's palette and background.
constexpr Rgb kGrey{0x44, 0x44, 0x44};
constexpr Rgb kEmissive{0x07, 0x25, 0x34};
constexpr Rgb kDiffuse{0x15, 0x62, 0x89};
constexpr Rgb kFirstSpecular{0x11, 0x11, 0x11};  // three.js's default, until 0.1.6 raised it
constexpr Rgb kSpecular{0x44, 0x44, 0x44};
constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kGold{0xFF, 0xD7, 0x00};
constexpr float kPhongShininess = 30.0F;
constexpr Falloff kDiaryFalloff{0.5F, 0.0F, 1.0F};
constexpr glm::vec3 kTorusEye{0.0F, 0.5F, -1.0F};
constexpr float kLampHeight = -0.5F;
constexpr float kLampCircle = 0.45F;  // ours: the diary's still has the lamp at the centre

// The lights of each Phase 2 release, added to a scene.
void add_phase2_lights(Scene& scene, std::ptrdiff_t id) {
    if (id == kMaterials) {
        scene.lights = {{{1.0F, 2.0F, -1.0F}, 1.0F}};
    } else if (id == kThreeLights) {
        // three.js's three lights, z flipped into our left-handed world; its intensity 3 under a
        // Lambert term divided by pi is about 1 in the diary's formula, which has no pi.
        scene.lights = {{{0.0F, 2.0F, 0.0F}, 1.0F}, {{1.0F, 2.0F, -1.0F}, 1.0F}, {{-1.0F, -2.0F, 1.0F}, 1.0F}};
    } else {  // 0.1.6 on: one directional light from above and two point lights at the corners
        scene.lights = {{{0.0F, 2.0F, 0.0F}, 0.5F}};
        scene.point_lights = {{{1.0F, 2.0F, -1.0F}, 3.0F, kDiaryFalloff}, {{-1.0F, -2.0F, 1.0F}, 3.0F, kDiaryFalloff}};
    }
}

LinearMaterial torus_material(std::ptrdiff_t id) {
    return LinearMaterial::from_srgb(kEmissive, kDiffuse, id < kPointLights ? kFirstSpecular : kSpecular,
                                     kPhongShininess);
}

glm::mat4 scale(glm::vec3 s) { return glm::scale(glm::mat4(1.0F), s); }
glm::mat4 scale(float s) { return scale(glm::vec3(s)); }

// The tumble of the cube scenes at another size, by a fraction of a turn.
glm::mat4 tumble(double turn, float size) {
    return tumble_rotation(static_cast<float>(2.0 * std::numbers::pi * turn)) * scale(size);
}

glm::vec3 orbit_eye(double turn) {
    const double angle = 2.0 * std::numbers::pi * turn;
    return {static_cast<float>(std::sin(angle)), kOrbitHeight, static_cast<float>(-std::cos(angle))};
}

// Where frame `index` of `count` stands in a two-half clip: which half, and how far through it.
struct HalfClip {
    bool second;
    double u;
};
HalfClip half_clip(int index, int count) {
    const int half = std::max(count / 2, 1);
    const bool second = index >= half;
    const int in_half = second ? index - half : index;
    return {second, static_cast<double>(in_half) / (second ? std::max(count - half, 1) : half)};
}

// The squash of 0.0.12 to 0.0.15: y eases from 0.75 to `low` and back, x and z to `wide`.
glm::mat4 squash(double u, float wide, float low) {
    const auto s = static_cast<float>(std::sin(std::numbers::pi * ease_in_out_cubic(u)));
    return scale({0.75F + (wide - 0.75F) * s, 0.75F + (low - 0.75F) * s, 0.75F + (wide - 0.75F) * s});
}

Scene lit_scene(OrthoCamera camera, glm::vec3 light) {
    return Scene{camera, Rgb{0, 0, 0}, {DirectionalLight{light}}, {}, {}};
}

glm::mat4 placed(glm::vec3 centre, float radius) { return glm::translate(glm::mat4(1.0F), centre) * scale(radius); }

}  // namespace

std::span<const SceneInfo> diary_scenes() noexcept { return kScenes; }

const SceneInfo& final_diary_scene() noexcept { return kScenes[kPointLights]; }

double ease_in_out_cubic(double u) noexcept {
    return u < 0.5 ? 4.0 * u * u * u : 1.0 - std::pow(-2.0 * u + 2.0, 3.0) / 2.0;
}

DiaryScene::DiaryScene(std::string_view name) : info_(nullptr), analytic_(ShapeKind::sphere) {
    std::string names;
    for (const SceneInfo& scene : kScenes) {
        if (scene.name == name) info_ = &scene;
        names += (names.empty() ? "" : ", ") + std::string(scene.name);
    }
    if (info_ == nullptr) throw std::invalid_argument("no scene '" + std::string(name) + "'; the scenes are " + names);
    switch (info_ - kScenes.data()) {
    case kLitCube: shape_ = std::make_shared<const Mesh>(cube_mesh()); break;
    case kDodecahedron: shape_ = std::make_shared<const Mesh>(dodecahedron()); break;
    case kOrbit:  // its still is the cube seen from the raised eye, as still-cube showed it
        shape_ = std::make_shared<const Mesh>(dodecahedron());
        still_shape_ = std::make_shared<const Mesh>(cube_mesh());
        break;
    case kFacetedSphere:
        shape_ = std::make_shared<const Mesh>(sphere(4));
        still_shape_ = std::make_shared<const Mesh>(sphere(0));
        break;
    case kSmoothSphere:
    case kGlossySphere:
        shape_ = std::make_shared<const Mesh>(sphere(4));
        still_shape_ = std::make_shared<const Mesh>(sphere(3));
        break;
    case kTwoSpheres:
        shape_ = std::make_shared<const Mesh>(sphere(4));
        ground_ = std::make_shared<const Mesh>(
            ground_quad({-1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, -1.0F}, {1.0F, 0.0F, 1.0F}, {-1.0F, 0.0F, 1.0F}));
        break;
    case kTorus:
    case kMaterials:
    case kThreeLights:
    case kPointLights:
    case kShaders: shape_ = std::make_shared<const Mesh>(torus(48, 32)); break;
    case kPointLight:  // the lamp's marker over the diary's trapezoid of ground
        shape_ = std::make_shared<const Mesh>(sphere(2));
        ground_ = std::make_shared<const Mesh>(
            ground_quad({-0.9F, -0.7F, -0.9F}, {0.9F, -0.7F, -0.9F}, {0.6F, -0.7F, 0.9F}, {-0.6F, -0.7F, 0.9F}));
        break;
    default: shape_ = std::make_shared<const Mesh>(sphere(4)); break;
    }
    if (!still_shape_) still_shape_ = shape_;
    const auto id = info_ - kScenes.data();
    analytic_ = id >= kTorus && id != kPointLight ? ShapeKind::torus : ShapeKind::sphere;
}

Scene DiaryScene::still(int width, int height) const { return tagged(untagged_still(width, height)); }

Scene DiaryScene::frame(int width, int height, int index, int count) const {
    return tagged(untagged_frame(width, height, index, count));
}

// Marks the objects whose meshes stand for a sphere or the torus, so their detail can be chosen.
Scene DiaryScene::tagged(Scene scene) const {
    for (SceneObject& object : scene.objects) {
        if (object.mesh != ground_ && object.mesh->surface == Surface::smooth) object.shape = analytic_;
    }
    return scene;
}

Scene DiaryScene::untagged_still(int width, int height) const {
    if (is_phase2(info_ - kScenes.data())) return phase2(width, height, std::nullopt);
    const OrthoCamera front(width, height);
    const OrthoCamera raised = OrthoCamera::look_at(width, height, kStillEye);
    const IntensityMaterial matte = IntensityMaterial::matte(kShapeColour, 0.25F);
    const IntensityMaterial shiny = IntensityMaterial::shiny(kShapeColour, 0.15F, 100.0F);
    switch (info_ - kScenes.data()) {
    case kLitCube:
    case kDodecahedron:
    case kOrbit: {  // the still pose; 0.0.10 raised the eye
        Scene scene = lit_scene(info_ - kScenes.data() == kOrbit ? raised : front, kSunFromRight);
        scene.objects.push_back({still_shape_, still_cube_pose(), matte, ShadingMethod::flat});
        return scene;
    }
    case kFacetedSphere: {
        Scene scene = lit_scene(raised, kSunFromRight);
        scene.objects.push_back(
            {still_shape_, scale(0.5F), IntensityMaterial::matte(kShapeColour, 0.1F), ShadingMethod::flat});
        return scene;
    }
    case kSmoothSphere:
    case kGlossySphere: {
        Scene scene = lit_scene(raised, kSunFromRight);
        const bool glossy = info_ - kScenes.data() == kGlossySphere;
        scene.objects.push_back({still_shape_, scale(0.5F),
                                 glossy ? shiny : IntensityMaterial::matte(kShapeColour, 0.2F),
                                 ShadingMethod::gouraud});
        return scene;
    }
    case kSquash: {
        Scene scene = lit_scene(raised, kHighLeftLamp);
        scene.objects.push_back({shape_, scale({0.7F, 0.15F, 0.7F}), shiny, ShadingMethod::gouraud});
        return scene;
    }
    case kPhongSphere: {
        Scene scene = lit_scene(front, kHighLeftLamp);
        scene.objects.push_back({shape_, scale(0.7F), shiny, ShadingMethod::phong});
        return scene;
    }
    case kTwoSpheres: {
        Scene scene = lit_scene(OrthoCamera::look_at(width, height, {0.0F, 0.5F, -1.0F}), kHighLeftLamp);
        scene.objects.push_back(
            {ground_, glm::mat4(1.0F), IntensityMaterial::matte(kTerracotta, 0.15F), ShadingMethod::flat});
        scene.objects.push_back({shape_, placed({0.0F, 0.25F, 0.0F}, 0.5F), shiny, ShadingMethod::phong});
        return scene;
    }
    default: {
        Scene scene = lit_scene(OrthoCamera::look_at(width, height, {0.0F, 0.5F, -1.0F}), kHighLeftLamp);
        scene.objects.push_back({shape_, scale(0.8F), shiny, ShadingMethod::phong});
        return scene;
    }
    }
}

Scene DiaryScene::untagged_frame(int width, int height, int index, int count) const {
    if (is_phase2(info_ - kScenes.data())) return phase2(width, height, tumble_angle(index, count));
    const double turn = static_cast<double>(index) / std::max(count, 1);
    const IntensityMaterial matte = IntensityMaterial::matte(kShapeColour, 0.25F);
    const IntensityMaterial shiny = IntensityMaterial::shiny(kShapeColour, 0.15F, 100.0F);
    const OrthoCamera pinned = OrthoCamera::look_at(width, height, {0.0F, kOrbitHeight, -1.0F});
    const HalfClip clip = half_clip(index, count);
    switch (info_ - kScenes.data()) {
    case kLitCube:
    case kDodecahedron: {
        Scene scene = lit_scene(OrthoCamera(width, height), kSunFromRight);
        const float size = info_ - kScenes.data() == kLitCube ? 0.5F : 0.75F;
        const glm::mat4 model = tumble_rotation(tumble_angle(index, count)) * scale(size);
        scene.objects.push_back({shape_, model, matte, ShadingMethod::flat});
        return scene;
    }
    case kOrbit: {
        Scene scene =
            lit_scene(clip.second ? pinned : OrthoCamera::look_at(width, height, orbit_eye(clip.u)), kSunFromRight);
        scene.objects.push_back(
            {shape_, clip.second ? tumble(clip.u, 0.75F) : scale(0.75F), matte, ShadingMethod::flat});
        return scene;
    }
    case kFacetedSphere: {
        const double eased = ease_in_out_cubic(clip.u);
        Scene scene = lit_scene(clip.second ? pinned : OrthoCamera::look_at(width, height, orbit_eye(eased)), kLowSun);
        scene.objects.push_back(
            {shape_, clip.second ? tumble(eased, 0.75F) : scale(0.75F), matte, ShadingMethod::flat});
        return scene;
    }
    case kTwoSpheres: {
        Scene scene = lit_scene(OrthoCamera::look_at(width, height, orbit_eye(ease_in_out_cubic(turn))), kLowSun);
        scene.objects.push_back({shape_, placed({-0.5F, 0.0F, 0.0F}, 0.4F), shiny, ShadingMethod::phong});
        IntensityMaterial second = shiny;
        second.base = kSecondColour;
        scene.objects.push_back({shape_, placed({0.5F, 0.0F, 0.0F}, 0.3F), second, ShadingMethod::phong});
        return scene;
    }
    case kTorus: {
        Scene scene = lit_scene(OrthoCamera::look_at(width, height, {0.0F, 0.5F, -1.0F}), kLowSun);
        scene.objects.push_back(
            {shape_, tumble_rotation(tumble_angle(index, count)) * scale(0.8F), shiny, ShadingMethod::phong});
        return scene;
    }
    default: {  // the orbit-then-squash clips of 0.0.12 to 0.0.15
        const auto id = info_ - kScenes.data();
        Scene scene = lit_scene(
            clip.second ? pinned : OrthoCamera::look_at(width, height, orbit_eye(ease_in_out_cubic(clip.u))), kLowSun);
        const bool deep = id == kSquash || id == kPhongSphere;
        const glm::mat4 model = clip.second ? squash(clip.u, deep ? 0.95F : 0.75F, deep ? 0.2F : 0.4F) : scale(0.75F);
        scene.objects.push_back({shape_, model, id == kSmoothSphere ? matte : shiny,
                                 id == kPhongSphere ? ShadingMethod::phong : ShadingMethod::gouraud});
        return scene;
    }
    }
}

// The stills (no angle) and frames of Phase 2: the torus scenes tumble as 0.0.17's did, and the
// point light circles its ground.
Scene DiaryScene::phase2(int width, int height, std::optional<float> angle) const {
    const auto id = info_ - kScenes.data();
    Scene scene{OrthoCamera::look_at(width, height, kTorusEye), kGrey, {}, {}, {}};
    if (id == kPointLight) {
        scene.camera = OrthoCamera::look_at(width, height, {0.0F, 0.25F, -1.0F});
        const float a = angle.value_or(0.0F);
        const glm::vec3 lamp = angle ? glm::vec3(kLampCircle * std::sin(a), kLampHeight, -kLampCircle * std::cos(a))
                                     : glm::vec3(0.0F, kLampHeight, 0.0F);
        scene.point_lights = {{lamp, 1.0F, kDiaryFalloff}};
        scene.objects.push_back({ground_, glm::mat4(1.0F),
                                 LinearMaterial::from_srgb(kBlack, kDiffuse, kBlack, std::nullopt),
                                 ShadingMethod::phong});
        scene.objects.push_back({shape_, placed(lamp, 0.04F),
                                 LinearMaterial::from_srgb(kGold, kBlack, kBlack, std::nullopt), ShadingMethod::phong});
        return scene;
    }
    add_phase2_lights(scene, id);
    const glm::mat4 turn = angle ? tumble_rotation(*angle) : glm::mat4(1.0F);
    if (id == kShaders) {  // the same torus twice, the left one per pixel and the right one per vertex
        for (const auto& [x, method] :
             {std::pair{-0.6F, ShadingMethod::phong}, std::pair{0.6F, ShadingMethod::gouraud}}) {
            scene.objects.push_back({shape_, glm::translate(glm::mat4(1.0F), {x, 0.0F, 0.0F}) * turn * scale(0.55F),
                                     torus_material(id), method});
        }
        return scene;
    }
    scene.objects.push_back({shape_, turn * scale(0.8F), torus_material(id), ShadingMethod::phong});
    return scene;
}

}  // namespace raster
