#pragma once

#include <raster/image/colour.hpp>
#include <raster/shade/texture.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

// Tangent-space normal maps (doc/conventions.md#normal-maps): a texel's direction turned into the
// world by the vertex tangent frame, or by the frame the surface's changes per pixel define.
namespace raster {

// The unit normal `normal` leaned by the normal-map `texel` (linear, each channel 2 c - 1, x and y
// times `scale`), in the frame of the interpolated `tangent` (xyz, w the bitangent's sign; zero
// for none) made perpendicular to `normal`, else in the frame that the changes of position and
// texture coordinate per pixel define (Schüler's cotangent frame, which carries the mirror sign
// of the mapping with it). `normal` itself where there is no frame or the texel is no direction.
[[nodiscard]] glm::vec3 normal_mapped(glm::vec3 normal, LinearRgb texel, float scale, glm::vec4 tangent,
                                      glm::vec3 position_per_x, glm::vec3 position_per_y,
                                      const UvFootprint& footprint) noexcept;

}  // namespace raster
