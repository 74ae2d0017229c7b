#pragma once

#include <raster/image/colour.hpp>
#include <raster/shade/texture.hpp>

#include <glm/vec3.hpp>

// Tangent-space normal maps (doc/conventions.md#metallic-roughness): a texel's direction turned
// into the world by the frame the surface's changes per pixel define.
namespace raster {

// The unit normal `normal` leaned by the normal-map `texel` (linear, each channel 2 c - 1, x and y
// times `scale`), in the frame that the changes of position and texture coordinate per pixel
// define (Schüler's cotangent frame, which carries the mirror sign of the mapping with it).
// `normal` itself where there is no frame or the texel is no direction (128 128 128).
[[nodiscard]] glm::vec3 normal_mapped(glm::vec3 normal, LinearRgb texel, float scale, glm::vec3 position_per_x,
                                      glm::vec3 position_per_y, const UvFootprint& footprint) noexcept;

}  // namespace raster
