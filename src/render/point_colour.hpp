#pragma once

#include <raster/render/scene.hpp>

#include "rasterize/facet_corners.hpp"

#include <variant>

// The colour of a vertex drawn as a point or a line end: lit by the object's own shader when the
// vertex has a normal, else its colour times the material's (doc/conventions.md#points-and-lines).
namespace raster::detail {

template <typename Shader>
class PointColour {
public:
    PointColour(const Shader& shader, const SceneObject& object) : shader_(shader) {
        if (const auto* intensity = std::get_if<IntensityMaterial>(&object.material)) {
            base_ = linear_from_srgb(intensity->base);
        } else {
            base_ = std::get<LinearMaterial>(object.material).diffuse;
        }
    }

    // Vertex i of `posed` (world positions and normals); checked by check_drawable.
    [[nodiscard]] LinearRgb linear(const Mesh& posed, std::size_t i) const noexcept {
        const LinearRgb tint = posed.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : posed.colours[i];
        if (unit_or_zero(posed.normals[i]) == glm::vec3(0.0F)) return base_ * tint;  // no normal: nothing to light
        return linear_from_srgb(lit(posed, i));
    }
    [[nodiscard]] Rgb srgb(const Mesh& posed, std::size_t i) const noexcept {
        const LinearRgb tint = posed.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : posed.colours[i];
        if (unit_or_zero(posed.normals[i]) == glm::vec3(0.0F)) return srgb_from_linear(base_ * tint);
        return lit(posed, i);
    }

private:
    [[nodiscard]] Rgb lit(const Mesh& posed, std::size_t i) const noexcept {
        const typename Shader::Varying v = vertex_varying(shader_, posed, i);
        if constexpr (NeedsFootprint<Shader>) {
            return shader_.pixel(v, v - v, v - v);  // a point samples its texture at the finest level
        } else {
            return shader_.pixel(v);
        }
    }

    const Shader& shader_;
    LinearRgb base_;
};

}  // namespace raster::detail
