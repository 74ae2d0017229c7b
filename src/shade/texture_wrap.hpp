#pragma once

#include <raster/shade/texture.hpp>

#include <algorithm>
#include <cmath>

// How a texture extends beyond its edges, for one texel read and for lanes alike.
namespace raster::detail {

// The coordinate brought into [0, 1] the way `wrap` extends the image; NaN and infinities go to 0.
inline float wrapped(float coordinate, TextureWrap wrap) noexcept {
    if (!std::isfinite(coordinate)) return 0.0F;
    if (wrap == TextureWrap::clamp) return std::clamp(coordinate, 0.0F, 1.0F);
    const float fraction = coordinate - std::floor(coordinate);
    return fraction < 1.0F ? fraction : 0.0F;  // a tiny negative value rounds up to exactly 1
}

// Texel index i of a side of n texels, beyond the edge by at most one, brought back inside.
inline int wrapped_index(int i, int n, TextureWrap wrap) noexcept {
    if (wrap == TextureWrap::clamp) return std::clamp(i, 0, n - 1);
    return i < 0 ? n - 1 : (i >= n ? 0 : i);
}

}  // namespace raster::detail
