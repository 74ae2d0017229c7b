#pragma once

#include <raster/geometry/shapes.hpp>

#include <optional>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

// The true surfaces the diary's smooth meshes approximate, in object space, in double precision:
// what automatic detail and the lab's ray caster measure meshes against.
namespace raster {

// Signed distance to the surface: negative inside.
[[nodiscard]] double distance_to_surface(ShapeKind shape, glm::dvec3 p) noexcept;

// The unit normal of the surface point nearest p (the distance function's gradient).
[[nodiscard]] glm::dvec3 surface_normal(ShapeKind shape, glm::dvec3 p) noexcept;

// The smallest t at which the whole line o + t d meets the surface (t may be negative): exact
// for the sphere, sphere tracing to 1e-12 with the exact distance function for the torus.
// Nothing when the line misses.
[[nodiscard]] std::optional<double> first_hit(ShapeKind shape, glm::dvec3 o, glm::dvec3 d) noexcept;

// The least and greatest factor by which a model matrix stretches a direction (the extreme
// singular values of its linear part); zero for a singular one.
struct Stretch {
    double least;
    double most;
};
[[nodiscard]] Stretch model_stretch(const glm::mat4& model) noexcept;

}  // namespace raster
