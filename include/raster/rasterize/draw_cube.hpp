#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/cube.hpp>
#include <raster/image/framebuffer.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace raster {

// Slots of the faces that turn toward the camera on screen: positive snapped area, the same
// numbers the fill uses, so a face seen edge-on is culled rather than drawn as a stray line.
[[nodiscard]] std::vector<std::size_t> faces_toward_camera(const OrthoCamera& camera, const Cube& cube);

// Fills each face toward the camera with its palette colour. A convex cube needs no depth
// buffer: culling alone leaves no overlapping faces.
void draw_faces(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube,
                const std::array<Rgb, 6>& palette);

enum class EdgeSelection { all, front_facing };

// Draws the cube's edges as lines: all twelve, or only those of faces toward the camera.
void draw_edges(Framebuffer& framebuffer, const OrthoCamera& camera, const Cube& cube, EdgeSelection selection,
                Rgb colour);

}  // namespace raster
