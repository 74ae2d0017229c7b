#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/mesh.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/rasterize/depth_buffer.hpp>
#include <raster/rasterize/shader.hpp>

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
// Instantiated for the library's shaders in src/shade/draw_mesh_shaders.cpp; another shader
// is drawn through the rasterizer's private headers (src/rasterize/setup_ortho.hpp).
template <Shader S>
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const S& shader);

}  // namespace raster
