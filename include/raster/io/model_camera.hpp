#pragma once

#include <optional>
#include <string>
#include <glm/vec3.hpp>

// A camera a model file carries (glTF's, doc/conventions.md#model-cameras), placed by its node
// in the file's own coordinates (right-handed, as ModelView's): where it stands, where it looks
// and its lens, in model units.
namespace raster {

struct ModelCamera {
    std::string name;
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};  // unit: the node's -Z
    glm::dvec3 up{0.0, 1.0, 0.0};        // unit, square to forward: the node's +Y
    bool orthographic = false;
    double yfov_degrees = 40.0;  // perspective: the vertical field of view
    double half_height = 1.0;    // orthographic: ymag, half the view's height
    double near = 0.0;           // perspective: znear
    std::optional<double> far;   // perspective: zfar; none for an infinite projection
};

}  // namespace raster
