#pragma once

#include <raster/cube.hpp>
#include <raster/framebuffer.hpp>
#include <raster/ortho_camera.hpp>

#include <array>

namespace raster {

// Fills each front-facing face with its palette colour. A convex cube needs no depth buffer:
// culling alone leaves no overlapping faces.
void draw_faces(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube,
                const std::array<Rgb, 6>& palette);

enum class EdgeSelection { all, front_facing };

// Draws the cube's edges as lines: all twelve, or only those of front-facing faces.
void draw_edges(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube,
                EdgeSelection selection, Rgb colour);

}  // namespace raster
