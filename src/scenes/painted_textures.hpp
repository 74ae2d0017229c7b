#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/shade/texture.hpp>

#include <cstdint>
#include <functional>
#include <memory>

// Textures painted in code for the seed scenes: the originals' images are not ours to ship.
// Each is 64 x 64 texels and repeats seamlessly unless it says otherwise.
namespace raster::detail {

// A repeatable value in [0, 1) for texel (x, y) of pattern `seed`: texture grain without state.
[[nodiscard]] float grain(int x, int y, std::uint32_t seed);
// `base` scaled by `k`, each channel clamped to a byte.
[[nodiscard]] Rgb shaded(Rgb base, float k);
[[nodiscard]] std::shared_ptr<const Texture> painted(int width, int height, const std::function<Rgb(int, int)>& paint);

// Overlapping round scales in rows, gold to green at their rims: the Ptah knot's skin.
[[nodiscard]] std::shared_ptr<const Texture> scales();
// `base` with random brightness within +-`spread`: grass, sand, rock, leaves.
[[nodiscard]] std::shared_ptr<const Texture> speckled(Rgb base, float spread, std::uint32_t seed);
[[nodiscard]] std::shared_ptr<const Texture> bricks();
// Boards `width` texels wide with dark joints, running along u.
[[nodiscard]] std::shared_ptr<const Texture> planks(Rgb base, int width);
// Rolling crests of sea water.
[[nodiscard]] std::shared_ptr<const Texture> waves();
[[nodiscard]] std::shared_ptr<const Texture> sail();
// Foaming streaks running along v, for falling and flowing water.
[[nodiscard]] std::shared_ptr<const Texture> streaks();
// Asphalt with a dashed white centre line along v at u = 1/2, and white edges.
[[nodiscard]] std::shared_ptr<const Texture> runway();
// Ribbed grey metal sheet, the ribs running along v.
[[nodiscard]] std::shared_ptr<const Texture> corrugated();
// White paint with a red band across v = 1/2: an aeroplane's livery.
[[nodiscard]] std::shared_ptr<const Texture> livery();
// Dark blue panes in white frames.
[[nodiscard]] std::shared_ptr<const Texture> windows();

}  // namespace raster::detail
