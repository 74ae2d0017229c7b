#pragma once

#include <raster/render/scene.hpp>

#include <cstddef>

// raster-engine's render modes, on any scene: its textures and light as they are, the same
// lit per facet in each surface's mean colour, or the edges of the facets that face the eye.
namespace raster {

enum class RenderStyle { textured, flat, wireframe };

// The scene with every texture replaced by its mean colour (its last mip level, averaged in
// linear light) and every surface lit once per facet.
[[nodiscard]] Scene flat_style(Scene scene);
[[nodiscard]] PerspectiveScene flat_style(PerspectiveScene scene);

// Clears to the background and draws, in each object's unlit mean colour, the edges of its
// facets that face the eye (back faces culled, nothing hidden by depth), as one-pixel DDA lines
// (doc/conventions.md#lines); in perspective each edge is first clipped to the near and far
// planes and the guard band. Returns the facets drawn.
std::size_t draw_wireframe(Framebuffer& framebuffer, const Scene& scene);
std::size_t draw_wireframe(Framebuffer& framebuffer, const PerspectiveScene& scene);

}  // namespace raster
