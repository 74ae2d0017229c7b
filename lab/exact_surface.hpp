#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/shapes.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/shade/intensity_lighting.hpp>

#include <cstdint>
#include <span>
#include <vector>
#include <glm/mat4x4.hpp>

// The exact shading reference: the true sphere or torus (raster::first_hit) ray-cast at every
// pixel centre along the orthographic view line (the whole line, as the rasterizer has no near
// plane), in double precision, shaded with the same model in double and rounded once.
namespace lab {

struct ExactObject {
    raster::ShapeKind shape;
    glm::mat4 model;
    raster::IntensityMaterial material;
};

struct ExactImage {
    raster::Framebuffer colour;
    std::vector<std::uint8_t> covered;  // 1 where a surface was hit, row-major
    std::vector<double> depth;          // the hit's view depth, row-major (+infinity for none)
};

// The intensity of the Phase 1 model in double precision for a unit normal.
[[nodiscard]] double exact_intensity(const raster::IntensityMaterial& material,
                                     std::span<const raster::DirectionalLight> lights, glm::dvec3 normal,
                                     glm::dvec3 to_eye);

[[nodiscard]] ExactImage ray_cast(const raster::OrthoCamera& camera, int width, int height,
                                  std::span<const ExactObject> objects,
                                  std::span<const raster::DirectionalLight> lights, raster::Rgb background);

}  // namespace lab
