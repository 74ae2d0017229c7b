#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/io/model.hpp>
#include <raster/rasterize/depth_buffer.hpp>
#include <raster/render/scene.hpp>

#include <memory>
#include <optional>
#include <string>
#include <glm/vec3.hpp>

// A model file's contents in front of a camera: what `render` draws (doc/conventions.md#models).
namespace raster {

// Which faces are drawn: a closed model's back faces never show, so `automatic` culls them only
// then and draws an open model (a leaf, a plane, a scan) from both sides, lit on each.
enum class Culling { automatic, back, none };

// How to look at a model. Points and directions are in the model file's own coordinates
// (right-handed, as OBJ is); what is left out is chosen from the model's bounding sphere.
struct ModelView {
    std::optional<glm::dvec3> eye;     // default: a three-quarter view from the front, right and above
    std::optional<glm::dvec3> target;  // default: the centre of the bounding box
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_degrees = 40.0;          // vertical; the sphere fills the narrower side of the view
    bool orthographic = false;          // then the sphere fills the shorter side, whatever the field of view
    std::optional<double> half_height;  // orthographic: model units from the middle to the top edge instead
    std::optional<double> near;         // model units; default just short of the sphere
    std::optional<double> far;          // default just beyond it
    std::optional<glm::dvec3> light;    // toward the key light; default from over the viewer's left shoulder
    ShadingMethod shading = ShadingMethod::phong;
    Rgb background{48, 52, 60};
    // The background is to be left transparent: depth is kept for every model, so that the
    // pixels drawn can be read afterwards (Renderer::coverage).
    bool transparent = false;
    Culling cull = Culling::automatic;
    // How the model's points and lines are drawn: splat size (default from their density) and line width.
    PointsAndLines points_and_lines{};
};

// `view` looking through a camera the model file carries (doc/conventions.md#model-cameras): its
// eye, direction, up and lens, near and far where it gives them; the target, about which a
// turntable turns, is the point ahead nearest the model's centre.
[[nodiscard]] ModelView through_camera(ModelView view, const ModelCamera& camera, const Model& model);

// What `--camera N` is refused with when the model has no camera N: how many it has, in one line.
[[nodiscard]] std::string camera_refusal(const Model& model, std::size_t index);

// A model placed for viewing, frame after frame.
class ModelStage {
public:
    // Throws std::invalid_argument for a view it cannot take (the eye on the target or looking
    // along `up`, a lens out of range, non-finite numbers) or a model too large to frame.
    ModelStage(std::shared_ptr<const Model> model, const ModelView& view, int width, int height);
    // The same, taking the model: meshes drawn as they are move into the stage rather than being
    // copied, so a model of millions of points is held once. The model is taken even if this throws.
    ModelStage(Model&& model, const ModelView& view, int width, int height);

    // Draws the model turned by `turn` radians about the up axis through the target: a
    // turntable's frame. Returns the facets drawn.
    std::size_t render(Framebuffer& frame, DepthBuffer& depth, double turn = 0.0, RenderOptions options = {}) const;
    // The same with a renderer's threads and depth buffer, kept from frame to frame; `times`, when
    // given, receives the time of building the frame's scene (prepare) and of drawing it.
    std::size_t render(Framebuffer& frame, Renderer& renderer, double turn = 0.0, StageTimes* times = nullptr) const;

private:
    // `owned`, when given, is the model, whose meshes the stage may take.
    ModelStage(std::shared_ptr<const Model> model, const std::shared_ptr<Model>& owned, const ModelView& view,
               int width, int height);
    [[nodiscard]] std::vector<SceneObject> objects(double turn) const;
    template <typename Draw>
    std::size_t posed_scene(double turn, Draw draw) const;

    std::shared_ptr<const Model> model_;
    std::vector<std::shared_ptr<const Mesh>> meshes_;
    ShadingMethod shading_;
    // The camera and lights, one of the two; objects are added per frame.
    std::optional<PerspectiveScene> perspective_;
    std::optional<Scene> orthographic_;
    glm::dvec3 target_;  // in the unit sphere's coordinates
    glm::dvec3 up_;
};

// Gives every part that has texture coordinates `texture` as its diffuse map (a part with the
// default material takes white as its colour, so the map shows as it is); returns a warning for
// each part left without (empty when none).
std::vector<std::string> replace_diffuse_maps(Model& model, const std::shared_ptr<const Texture>& texture,
                                              const std::string& texture_name);

}  // namespace raster
