#pragma once

#include <raster/io/model.hpp>

#include <cstddef>
#include <string>
#include <vector>

// Vertex alpha as every reader takes it (doc/conventions.md#vertex-alpha): each value a file
// gives, and what a part's alphas do under its material.
namespace raster::detail {

// A file's vertex alpha: itself within [0, 1], clamped when outside it, 1 when not a number;
// `unreadable` counts those that were not within [0, 1].
[[nodiscard]] float vertex_alpha(float written, std::size_t& unreadable) noexcept;

// The one warning for a file's `unreadable` vertex alphas, none when there were none.
void warn_of_vertex_alphas(const std::string& file, std::size_t unreadable, std::vector<std::string>& warnings);

// A part's alphas under its material: kept where it blends or masks. An opaque glTF material
// ignores them (glTF 2.0: OPAQUE ignores alpha), and they are dropped; another format's opaque
// part with facets blends by them, as its opacity below 1 would; a part of points alone, drawn
// opaque, keeps none.
void settle_vertex_alphas(ModelPart& part, bool gltf) noexcept;

}  // namespace raster::detail
