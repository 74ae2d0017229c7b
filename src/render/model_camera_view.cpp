#include <raster/render/model_scene.hpp>

#include <string>
#include <glm/geometric.hpp>

namespace raster {

ModelView through_camera(ModelView view, const ModelCamera& camera, const Model& model) {
    const Bounds bounds = bounds_of(model);
    // The bounds are in raster's world, the camera in the file's: z mirrored back.
    const glm::dvec3 centre = bounds.centre() * glm::dvec3(1.0, 1.0, -1.0);
    const double ahead = glm::dot(centre - camera.eye, camera.forward);
    const double distance = ahead > 1e-6 * bounds.radius ? ahead : bounds.radius;
    view.eye = camera.eye;
    view.target = camera.eye + camera.forward * distance;
    view.up = camera.up;
    view.orthographic = camera.orthographic;
    if (camera.orthographic) {
        view.half_height = camera.half_height;
        view.near = view.far = std::nullopt;  // an orthographic view draws the whole model
        return view;
    }
    view.fov_degrees = camera.yfov_degrees;
    view.near = camera.near > 0.0 ? std::optional<double>(camera.near) : std::nullopt;
    view.far = camera.far;
    return view;
}

std::string camera_refusal(const Model& model, std::size_t index) {
    const std::size_t count = model.cameras.size();
    if (count == 0) return "--camera " + std::to_string(index) + ": the model carries no cameras";
    return "--camera " + std::to_string(index) + ": the model carries " + std::to_string(count) +
           (count == 1 ? " camera (--camera 0)" : " cameras (--camera 0 to " + std::to_string(count - 1) + ")");
}

}  // namespace raster
