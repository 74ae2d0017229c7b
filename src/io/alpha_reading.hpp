#pragma once

#include <raster/shade/opacity.hpp>

#include <string>
#include <vector>

// Alpha as the readers take it from a file (doc/conventions.md#transparency).
namespace raster::detail {

// The opacity of a surface whose file gives it `alpha`: blended below 1, else opaque. Outside
// [0, 1] it is clamped, not finite it is opaque, each with a warning that begins with `said`
// (the file, the material and the field).
[[nodiscard]] Opacity blended_by(float alpha, const std::string& said, std::vector<std::string>& warnings);

// A value from 0 to 1 the file gives (an alpha, a cutoff): itself, or `fallback` with a warning
// that begins with `said` when not finite, clamped with one when outside.
[[nodiscard]] float alpha_or(float value, float fallback, const std::string& said, std::vector<std::string>& warnings);

}  // namespace raster::detail
