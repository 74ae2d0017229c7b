#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/shade/shaders.hpp>

#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

// A shader for measuring the rasterizer itself: it keeps every world point it is handed and
// writes that point's index as the pixel's colour (24 bits), so a caller can tell afterwards
// which point each pixel was shaded with.
namespace lab {

struct RecordingShader {
    using Varying = glm::vec3;
    static constexpr bool kFacetNormal = false;
    std::vector<glm::vec3>* seen;
    [[nodiscard]] Varying vertex(const raster::Corner& corner) const noexcept { return corner.position; }
    [[nodiscard]] raster::Rgb pixel(const glm::vec3& world) const noexcept {
        const auto index = static_cast<std::uint32_t>(seen->size());
        seen->push_back(world);
        return {static_cast<std::uint8_t>(index >> 16), static_cast<std::uint8_t>(index >> 8),
                static_cast<std::uint8_t>(index)};
    }
};

// The index a RecordingShader wrote at (x, y); the background colour gives one past any index.
[[nodiscard]] inline std::uint32_t recorded_index(const raster::Framebuffer& image, int x, int y) {
    const raster::Rgb c = image.pixel(x, y);
    return (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
}

}  // namespace lab
