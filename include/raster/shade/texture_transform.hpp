#pragma once

#include <raster/shade/texture.hpp>

#include <glm/vec2.hpp>

// glTF's KHR_texture_transform on one map (doc/conventions.md#texture-transform): the map is
// read at T * R * S * uv, in glTF's texture frame (v down from the image's top), while raster's
// coordinates run v up, as OBJ's (raster/shade/texture.hpp); the frame is turned over around it.
namespace raster {

struct TextureTransform {
    glm::vec2 offset{0.0F};
    float rotation = 0.0F;  // radians, counter-clockwise as the specification's matrix turns the coordinates
    glm::vec2 scale{1.0F, 1.0F};

    // The transform that moves nothing: every map of a file without the extension.
    [[nodiscard]] bool identity() const noexcept {
        return offset == glm::vec2(0.0F) && rotation == 0.0F && scale == glm::vec2(1.0F, 1.0F);
    }
    friend bool operator==(const TextureTransform&, const TextureTransform&) = default;
};

// Where a map with `transform` is read for a point at `uv`, and how far that moves per pixel.
struct MovedUv {
    glm::vec2 uv;
    UvFootprint footprint;
};
// The identity returns `uv` and `footprint` as they are, bit for bit.
[[nodiscard]] MovedUv moved_uv(const TextureTransform& transform, glm::vec2 uv, const UvFootprint& footprint) noexcept;

// moved_uv for the first `count` lanes of `uvs`.
[[nodiscard]] LaneUvs moved_lanes(const TextureTransform& transform, const LaneUvs& uvs, int count) noexcept;

}  // namespace raster
