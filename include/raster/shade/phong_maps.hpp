#pragma once

#include <raster/shade/texture.hpp>

#include <memory>

// The maps of a Phong (linear) material beyond its diffuse map, each multiplying its factor
// (doc/conventions.md#mtl-maps).
namespace raster {

struct PhongMaps {
    std::shared_ptr<const Texture> specular{};  // sRGB colour, times the specular colour (MTL map_Ks)
    std::shared_ptr<const Texture> emissive{};  // sRGB colour, times the emissive colour (MTL map_Ke)
    std::shared_ptr<const Texture> normal{};    // linear, tangent space (from MTL's bump map)

    [[nodiscard]] bool any() const noexcept { return specular || emissive || normal; }
};

}  // namespace raster
