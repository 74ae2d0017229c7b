#pragma once

#include <raster/render/scene.hpp>

#include "geometry/posing.hpp"
#include "rasterize/facet_corners.hpp"

#include <variant>

// The colour of a vertex drawn as a point or a line end: lit by the object's own shader when the
// vertex has a normal, else its colour times the material's (doc/conventions.md#points-and-lines).
namespace raster::detail {

// Vertex i of `mesh` moved by `pose`, as the vertex stage sees it (vertex_varying's corner of a
// posed copy); `position` is pose.position(mesh.positions[i]), already worked out.
inline Corner posed_corner(const Mesh& mesh, const VertexPose& pose, std::size_t i, glm::vec3 position) noexcept {
    return {position, pose.normal(mesh.normals[i]), mesh.uvs.empty() ? glm::vec2(0.0F) : mesh.uvs[i],
            mesh.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : mesh.colours[i]};
}

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

    // A vertex in the world (posed_corner: its normal already unit or zero), with its colour as tint.
    [[nodiscard]] LinearRgb linear(const Corner& vertex) const noexcept {
        if (vertex.normal == glm::vec3(0.0F)) return base_ * vertex.colour;  // no normal: nothing to light
        return linear_from_srgb(lit(vertex));
    }
    [[nodiscard]] Rgb srgb(const Corner& vertex) const noexcept {
        if (vertex.normal == glm::vec3(0.0F)) return srgb_from_linear(base_ * vertex.colour);
        return lit(vertex);
    }

private:
    [[nodiscard]] Rgb lit(const Corner& vertex) const noexcept {
        const typename Shader::Varying v = shader_.vertex(vertex);
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
