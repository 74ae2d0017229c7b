#pragma once

#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>

#include <concepts>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

// What the rasterizer asks of a shader (doc/conventions.md#shading): vertex() turns a corner
// into a Varying, which the rasterizer interpolates across the triangle, and pixel() turns the
// interpolated Varying into a colour. Shaders depend on this header; the rasterizer on no shader.
namespace raster {

// What the vertex stage sees of one corner, in world space, with its texture coordinate, its
// colour (white for a mesh without vertex colours), its tangent (zero for a mesh without) and its
// alpha (1 for a mesh without vertex alphas).
struct Corner {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv{0.0F};
    LinearRgb colour{1.0F, 1.0F, 1.0F};
    glm::vec4 tangent{0.0F};
    float alpha = 1.0F;
};

// A value the rasterizer can interpolate: v0 + w1 (v1 - v0) + w2 (v2 - v0).
template <typename Varying>
concept Interpolable = std::copyable<Varying> && std::default_initializable<Varying> &&
    requires(const Varying& a, const Varying& b, float k) {
    { a + b } -> std::convertible_to<Varying>;
    { a - b } -> std::convertible_to<Varying>;
    { a* k } -> std::convertible_to<Varying>;
};

// A pixel stage that also takes how its Varying changes per pixel step in x and y: texture
// filtering chooses its mip level from that.
template <typename S>
concept NeedsFootprint = requires(const S& shader, const typename S::Varying& v) {
    { shader.pixel(v, v, v) } -> std::convertible_to<Rgb>;
};

// kFacetNormal asks for the facet's normal (and its centroid as the position) at every corner
// instead of the vertex attributes.
template <typename S>
concept VertexStage = requires(const S& shader, const Corner& corner) {
    { S::kFacetNormal } -> std::convertible_to<bool>;
    { shader.vertex(corner) } -> std::convertible_to<typename S::Varying>;
};

template <typename S>
concept PlainPixelStage = requires(const S& shader, const typename S::Varying& v) {
    { shader.pixel(v) } -> std::convertible_to<Rgb>;
};

// pixel() takes the Varying alone, or with its footprint.
template <typename S>
concept Shader = Interpolable<typename S::Varying> && VertexStage<S> &&(PlainPixelStage<S> || NeedsFootprint<S>);

// A depth pass's shader: it carries nothing and colours nothing, so the rasterizer only tests
// and writes depth for it (doc/conventions.md#depth).
template <typename S>
concept DepthOnly = requires {
    requires S::kDepthOnly;
};

}  // namespace raster
