#include "io/derived_maps.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace raster::detail {
namespace {

std::uint8_t byte_of(float unit) noexcept {
    return static_cast<std::uint8_t>(std::lround(std::clamp(unit, 0.0F, 1.0F) * 255.0F));
}

// The texel of `image` nearest to texel (x, y) of a grid `width` x `height`.
float nearest_channel(const Framebuffer& image, int x, int y, int width, int height, char channel) noexcept {
    const auto scaled = [](int at, int from, int to) {
        return static_cast<int>(static_cast<std::int64_t>(at) * from / to);
    };
    return data_channel(image, scaled(x, image.width(), width), scaled(y, image.height(), height), channel);
}

}  // namespace

float data_channel(const Framebuffer& image, int x, int y, char channel) noexcept {
    const std::size_t at =
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width()) + static_cast<std::size_t>(x)) * 3;
    const std::span<const std::uint8_t> texel = image.bytes().subspan(at, 3);
    switch (channel) {
    case 'r': return static_cast<float>(texel[0]) / 255.0F;
    case 'g': return static_cast<float>(texel[1]) / 255.0F;
    case 'b': return static_cast<float>(texel[2]) / 255.0F;
    default: return static_cast<float>(texel[0] + texel[1] + texel[2]) / (3.0F * 255.0F);
    }
}

Texture roughness_metallic_map(const Texture* roughness, char roughness_channel, const Texture* metallic,
                               char metallic_channel) {
    int width = 1, height = 1;
    std::size_t most = 0;  // the size of the map with more texels: two thin maps make no square one
    for (const Texture* map : {roughness, metallic}) {
        const std::size_t texels =
            map == nullptr ? 0 : static_cast<std::size_t>(map->width()) * static_cast<std::size_t>(map->height());
        if (texels > most) most = texels, width = map->width(), height = map->height();
    }
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    std::size_t at = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x, at += 3) {
            const auto read = [&](const Texture* map, char channel) {
                return map == nullptr ? 1.0F : nearest_channel(map->level(0), x, y, width, height, channel);
            };
            bytes[at + 1] = byte_of(read(roughness, roughness_channel));
            bytes[at + 2] = byte_of(read(metallic, metallic_channel));
        }
    }
    return Texture(Framebuffer(width, height, std::move(bytes)), TexelEncoding::linear);
}

Texture normals_from_heights(const Texture& heights, char channel, float scale, TextureWrap wrap) {
    const Framebuffer& image = heights.level(0);
    const int width = image.width(), height = image.height();
    const float k = std::isfinite(scale) ? scale : 1.0F;
    const auto at = [&](int x, int y) {
        if (wrap == TextureWrap::repeat) {
            x = (x % width + width) % width, y = (y % height + height) % height;
        } else {
            x = std::clamp(x, 0, width - 1), y = std::clamp(y, 0, height - 1);
        }
        return data_channel(image, x, y, channel) * k;
    };
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    std::size_t i = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x, i += 3) {
            // Row 0 is the top, v = 1: the slope along v runs from the row below to the row above.
            const float along_u = (at(x + 1, y) - at(x - 1, y)) * 0.5F;
            const float along_v = (at(x, y - 1) - at(x, y + 1)) * 0.5F;
            const float length = std::sqrt(along_u * along_u + along_v * along_v + 1.0F);
            bytes[i] = byte_of((-along_u / length) * 0.5F + 0.5F);
            bytes[i + 1] = byte_of((-along_v / length) * 0.5F + 0.5F);
            bytes[i + 2] = byte_of((1.0F / length) * 0.5F + 0.5F);
        }
    }
    return Texture(Framebuffer(width, height, std::move(bytes)), TexelEncoding::linear);
}

}  // namespace raster::detail
