#pragma once

#include <raster/shade/texture.hpp>

// Data maps built once at load time from maps a file gives in another form: MTL's separate
// roughness and metallic maps, and its height (bump) maps (doc/conventions.md#mtl-pbr).
namespace raster::detail {

// One channel of a map's texels as data, byte / 255: 'r', 'g' or 'b' as MTL's -imfchan names
// it; any other (tinyobjloader's default 'm', 'l', 'z') the mean of the three.
// (x, y) must lie inside the image.
[[nodiscard]] float data_channel(const Framebuffer& image, int x, int y, char channel) noexcept;

// One linear map holding roughness in green and metallic in blue, as MetallicRoughness reads
// them; either map may be null, and its channel is then 255 (its factor alone). Each is read
// at the nearest texel of a grid the size of the one with more texels. Red is 0.
[[nodiscard]] Texture roughness_metallic_map(const Texture* roughness, char roughness_channel, const Texture* metallic,
                                             char metallic_channel);

// A tangent-space normal map (linear bytes) from a height map: heights are the channel's
// byte / 255 times `scale` (MTL's -bm), in texel widths; slopes are central differences,
// wrapped or clamped at the edges as the map is sampled.
[[nodiscard]] Texture normals_from_heights(const Texture& heights, char channel, float scale, TextureWrap wrap);

}  // namespace raster::detail
