#pragma once

#include <raster/rasterize/depth_buffer.hpp>
#include <raster/rasterize/framebuffer.hpp>
#include <raster/geometry/mesh.hpp>
#include <raster/camera/ortho_camera.hpp>
#include <raster/shade/shaders.hpp>
#include <raster/shade/textured_shaders.hpp>

#include <cstddef>
#include <optional>
#include <raster/rasterize/fill.hpp>

namespace raster {

// Where a mesh is drawn: the colour buffer and, for scenes that need it, a prepared depth
// buffer of the same size (nullptr: no depth test).
struct RenderTarget {
    Framebuffer& colour;
    DepthBuffer* depth = nullptr;
    // The band of rows to draw into, such as one strip of a frame; nothing: every row.
    std::optional<PixelRect> rows = std::nullopt;
};

// Draws the facets of a posed mesh that face the camera (positive snapped area, the numbers
// the fill uses) through the exact convex fill, the shader's Varying interpolated at each
// covered pixel centre. With a depth buffer a pixel is kept unless something nearer is already
// there; ties go to the later facet (doc/conventions.md#depth). Returns the facets drawn.
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const FlatShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const GouraudShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const PhongShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const LinearFlatShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const LinearGouraudShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const LinearPhongShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const UnlitShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const TexturedFlatShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const TexturedGouraudShader& shader);
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const TexturedPhongShader& shader);

}  // namespace raster
