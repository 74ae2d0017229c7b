// ModelStage stays whole: the framing checks, the staged meshes and each frame's scene read together.
#include <raster/render/model_scene.hpp>

#include <raster/geometry/tangents.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace raster {

namespace {

// OBJ's right-handed coordinates into raster's left-handed world: z mirrored.
glm::dvec3 mirrored(glm::dvec3 v) noexcept { return {v.x, v.y, -v.z}; }

bool finite(glm::dvec3 v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The largest bounding sphere framed: beyond it float positions lose the detail of the model.
constexpr double kLargestRadius = 1e30;

// The default eye's direction from the target, in the file's coordinates: 35 degrees round from
// the front toward the right and 25 degrees up, "front" being +Z (or, for a Z-up model, -Y).
glm::dvec3 three_quarter_direction(glm::dvec3 up) {
    const glm::dvec3 u = glm::normalize(up);
    glm::dvec3 front = glm::dvec3(0, 0, 1) - u.z * u;
    if (glm::length(front) < 0.1) front = glm::dvec3(0, -1, 0) - u.y * u;
    front = glm::normalize(front);
    const glm::dvec3 right = glm::cross(u, front);
    const double around = 35.0 * std::numbers::pi / 180.0, above = 25.0 * std::numbers::pi / 180.0;
    return std::cos(above) * (std::cos(around) * front + std::sin(around) * right) + std::sin(above) * u;
}

// A number as people write it (%g), for messages.
std::string shown(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

bool lacks_tangent(const glm::vec4& t) { return glm::vec3(t) == glm::vec3(0.0F); }

// Whether the part's normal map needs tangents its mesh lacks, for some vertices or all.
bool needs_tangents(const ModelPart& part) {
    const Mesh& given = part.mesh;
    return part.metallic_roughness && part.metallic_roughness->normal_map &&
           (given.tangents.size() != given.positions.size() ||
            std::any_of(given.tangents.begin(), given.tangents.end(), lacks_tangent));
}

// The mesh the stage draws for the part, copied once (a model of millions of points is large),
// with tangents made from its texture coordinates where its normal map needs them and the file
// gave none, for the whole part or for some vertices (doc/conventions.md#normal-maps).
// `tangents` is needs_tangents(part), which the caller has already worked out.
Mesh staged_mesh(const ModelPart& part, bool both, bool tangents) {
    const Mesh& given = part.mesh;
    if (!tangents) return both ? both_sides(given) : given;
    const bool whole = given.tangents.size() == given.positions.size();
    Mesh mesh = given;
    const std::vector<glm::vec4> made = tangents_from_uvs(mesh);
    if (!whole) mesh.tangents = made;
    for (std::size_t i = 0; whole && i < made.size(); ++i) {
        if (lacks_tangent(mesh.tangents[i])) mesh.tangents[i] = made[i];
    }
    return both ? both_sides(mesh) : mesh;
}

// The lens limits of PerspectiveCamera, in unit-sphere distances.
constexpr double kNearest = 1e-18, kFarthest = 1e18;

}  // namespace

ModelStage::ModelStage(std::shared_ptr<const Model> model, const ModelView& view, int width, int height)
    : ModelStage(std::move(model), nullptr, view, width, height) {}

ModelStage::ModelStage(Model&& model, const ModelView& view, int width, int height)
    : ModelStage(nullptr, std::make_shared<Model>(std::move(model)), view, width, height) {}

ModelStage::ModelStage(std::shared_ptr<const Model> model, const std::shared_ptr<Model>& owned, const ModelView& view,
                       int width, int height)
    : model_(owned ? owned : std::move(model)), shading_(view.shading) {
    check_points_and_lines(view.points_and_lines);  // refused before the model is framed
    if (!model_) throw std::invalid_argument("no model to stage");
    const Bounds bounds = bounds_of(*model_);
    const double radius = bounds.radius;
    const glm::dvec3 centre = bounds.centre();
    if (!(radius > 0.0) || !(radius < kLargestRadius) || !finite(centre)) {
        throw std::invalid_argument("the model is too large (or too flat) to frame: bounding radius " + shown(radius));
    }
    // Positions moved into the unit sphere in double, so a model far from the origin keeps its detail;
    // an orthographic view of a given height takes its unit from that height on the shorter side.
    if (view.half_height && !(*view.half_height > 0.0 && *view.half_height < kLargestRadius))
        throw std::invalid_argument("the orthographic view's half height must be above 0, got " +
                                    shown(*view.half_height));
    const double shorter = static_cast<double>(std::min(width, height)) / static_cast<double>(std::max(height, 1));
    const double unit = view.orthographic && view.half_height ? *view.half_height * shorter : radius;
    const auto unit_from_world = [&](glm::dvec3 p) { return (p - centre) / unit; };
    const auto unit_from_file = [&](glm::dvec3 p) { return unit_from_world(mirrored(p)); };
    const std::vector<bool> open = open_parts(*model_);
    for (std::size_t i = 0; i < model_->parts.size(); ++i) {
        const ModelPart& part = model_->parts[i];
        const bool both = view.cull == Culling::none || (view.cull == Culling::automatic && open[i]);
        // A mesh the stage owns and draws as it is moves over, its positions moved in place.
        const bool tangents = needs_tangents(part), as_read = owned && !both && !tangents;
        auto mesh =
            std::make_shared<Mesh>(as_read ? std::move(owned->parts[i].mesh) : staged_mesh(part, both, tangents));
        if (owned) owned->parts[i].mesh = {};  // the staged copy is all the stage draws
        for (glm::vec3& p : mesh->positions) p = glm::vec3(unit_from_world(glm::dvec3(p)));
        meshes_.push_back(std::move(mesh));
    }
    if (!finite(view.up) || glm::length(view.up) == 0.0)
        throw std::invalid_argument("the up direction must be a non-zero vector");
    if (!(view.fov_degrees > 0.0 && view.fov_degrees < 180.0)) {
        throw std::invalid_argument("field of view must be between 0 and 180 degrees, got " + shown(view.fov_degrees));
    }
    up_ = glm::normalize(mirrored(view.up));
    target_ = view.target ? unit_from_file(*view.target) : glm::dvec3(0.0);
    glm::dvec3 eye;
    if (view.eye) {
        eye = unit_from_file(*view.eye);
    } else {
        // Far enough back that the unit sphere touches the narrower side of the view.
        const double half = view.fov_degrees * std::numbers::pi / 360.0;
        const double aspect = static_cast<double>(width) / static_cast<double>(height);
        const double narrower = std::min(half, std::atan(aspect * std::tan(half)));
        const double distance = view.orthographic ? 3.0 : 1.0 / std::sin(narrower);
        eye = target_ + mirrored(three_quarter_direction(view.up)) * distance;
    }
    if (!view.eye && !finite(eye))
        throw std::invalid_argument("--fov is too narrow to frame the model from any finite distance");
    if (!finite(eye) || !finite(target_))
        throw std::invalid_argument("--eye and --target must lie within float range of the model");

    if (!(glm::length(target_ - eye) > 1e-12)) {
        throw std::invalid_argument(
            view.target ? "--eye and --target are the same point; the camera needs a direction to look in"
                        : "--eye is the middle of the model, where the camera looks; move it, or give --target");
    }
    // The camera's axes, for the default lights: forward, right and up as the camera sees them.
    const glm::dvec3 forward = glm::normalize(target_ - eye);
    const glm::dvec3 side = glm::cross(up_, forward);
    if (!(glm::length(side) > 1e-9))
        throw std::invalid_argument("the view runs along the up direction; give another --up or --eye");
    const glm::dvec3 right = glm::normalize(side), camera_up = glm::cross(forward, right);
    std::vector<DirectionalLight> lights;
    const glm::dvec3 key = view.light ? mirrored(*view.light) : -forward + 0.9 * camera_up - 0.7 * right;
    if (!finite(key) || glm::length(key) == 0.0)
        throw std::invalid_argument("the light direction must be a non-zero vector");
    lights.push_back({glm::vec3(glm::normalize(key)), 0.85F});
    // A dim fill from the other side, so that no face is left black.
    lights.push_back({glm::vec3(glm::normalize(-glm::normalize(key) + 0.3 * -forward)), 0.3F});
    // Prefiltered once for every frame, and only for a model whose materials reflect it.
    const bool reflects = std::any_of(model_->parts.begin(), model_->parts.end(),
                                      [](const ModelPart& part) { return part.metallic_roughness.has_value(); });
    const auto surroundings = reflects ? std::make_shared<const Surroundings>(Surroundings::studio()) : nullptr;

    if (view.orthographic) {
        if (view.near || view.far)
            throw std::invalid_argument(
                "--near and --far set a perspective lens; an orthographic view draws the whole model");
        orthographic_ = Scene{OrthoCamera::look_at(width, height, glm::vec3(eye), glm::vec3(target_), glm::vec3(up_)),
                              view.background,
                              lights,
                              {},
                              {},
                              {},
                              view.transparent,
                              view.points_and_lines,
                              surroundings};
        return;
    }
    if (view.near && view.far && !(*view.near < *view.far)) {
        throw std::invalid_argument("--near must be less than --far, got " + shown(*view.near) + " and " +
                                    shown(*view.far));
    }
    // Near and far hold the sphere, wherever the turn about the target takes it.
    const double reach = 1.0 + 2.0 * glm::length(target_);
    const double from_centre = glm::length(eye);
    const double near = view.near ? *view.near / radius : std::max((from_centre - reach) * 0.9, 1e-3);
    const double far = view.far ? *view.far / radius : (from_centre + reach) * 1.1;
    if (!(near >= kNearest))
        throw std::invalid_argument("--near must be at least " + shown(kNearest * radius) +
                                    " for a model of this size");
    if (!(far <= kFarthest)) {
        throw std::invalid_argument(
            view.far ? "--far must be at most " + shown(kFarthest * radius) + " for a model of this size"
                     : "--eye is too far from the model to draw it in perspective; move it closer, or add --ortho");
    }
    if (!(far > near)) {
        throw std::invalid_argument(
            view.far ? "--far ends before the model begins; give a larger --far, or a --near before it"
                     : "--near lies beyond the model; give a smaller --near, or a --far beyond it");
    }
    const PerspectiveCamera::Lens lens{view.fov_degrees, near, far};
    perspective_ = PerspectiveScene{
        PerspectiveCamera::look_at(width, height, glm::vec3(eye), glm::vec3(target_), glm::vec3(up_), lens),
        view.background,
        lights,
        {},
        {},
        {},
        view.transparent,
        view.points_and_lines,
        surroundings};
}

std::vector<SceneObject> ModelStage::objects(double turn) const {
    const glm::mat4 turned = glm::translate(glm::dmat4(1.0), target_) * glm::rotate(glm::dmat4(1.0), turn, up_) *
                             glm::translate(glm::dmat4(1.0), -target_);
    std::vector<SceneObject> objects;
    for (std::size_t i = 0; i < meshes_.size(); ++i) {
        const ModelPart& part = model_->parts[i];
        const SurfaceMaterial material =
            part.metallic_roughness ? SurfaceMaterial{*part.metallic_roughness} : SurfaceMaterial{part.material};
        objects.push_back({meshes_[i], turned, material, shading_, std::nullopt, part.texture, part.sampler,
                           part.opacity, part.phong_maps});
    }
    return objects;
}

// Hands `draw` the scene of this turn, orthographic or in perspective.
template <typename Draw>
std::size_t ModelStage::posed_scene(double turn, Draw draw) const {
    if (orthographic_) {
        Scene scene = *orthographic_;
        scene.objects = objects(turn);
        return draw(scene);
    }
    PerspectiveScene scene = *perspective_;
    scene.objects = objects(turn);
    return draw(scene);
}

std::size_t ModelStage::render(Framebuffer& frame, DepthBuffer& depth, double turn, RenderOptions options) const {
    return posed_scene(turn, [&](const auto& scene) { return raster::render(frame, scene, depth, options); });
}

std::size_t ModelStage::render(Framebuffer& frame, Renderer& renderer, double turn, StageTimes* times) const {
    if (times == nullptr) return posed_scene(turn, [&](const auto& scene) { return renderer.render(frame, scene); });
    Stopwatch building;  // the frame's scene: part of prepare
    return posed_scene(turn, [&](const auto& scene) {
        times->prepare.spent += building.lap();
        return renderer.render(frame, scene, times);
    });
}

std::vector<std::string> replace_diffuse_maps(Model& model, const std::shared_ptr<const Texture>& texture,
                                              const std::string& texture_name) {
    std::vector<std::string> warnings;
    for (ModelPart& part : model.parts) {
        if (part.mesh.uvs.empty()) {
            const std::string name =
                part.material_name.empty() ? "the default material" : "material '" + part.material_name + "'";
            warnings.push_back(texture_name + ": " + name + " has no texture coordinates; drawing its colour");
            continue;
        }
        part.texture = texture;
        if (part.metallic_roughness) part.metallic_roughness->base_colour_map = texture;
        // A map given to a model without materials shows as it is, not dimmed by the default grey.
        if (part.material_name.empty()) part.material.diffuse = LinearRgb{1.0F, 1.0F, 1.0F};
    }
    return warnings;
}

}  // namespace raster
