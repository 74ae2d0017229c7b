#pragma once

#include <cmath>
#include <optional>

// How much of what lies behind a surface shows through it (doc/conventions.md#transparency):
// any material carries one, read from MTL d and Tr or glTF alphaMode and base colour alpha.
namespace raster {

// opaque: alpha ignored; mask: drawn opaque where alpha >= cutoff, else not at all; blend:
// composited over what lies behind in exact depth order, in linear light.
enum class AlphaMode { opaque, mask, blend };

struct Opacity {
    AlphaMode mode = AlphaMode::opaque;
    float factor = 1.0F;  // the surface's alpha, multiplying its texture's alpha where it has one
    float cutoff = 0.5F;  // mask only
};

// Whether the object is composited rather than drawn over.
[[nodiscard]] inline bool blends(const Opacity& opacity) noexcept { return opacity.mode == AlphaMode::blend; }

// Whether a mask object with no texture alpha shows at all: its one alpha against its cutoff.
[[nodiscard]] inline bool shows(const Opacity& opacity) noexcept {
    return opacity.mode != AlphaMode::mask || opacity.factor >= opacity.cutoff;
}

// An alpha or cutoff a file gave: itself within [0, 1], clamped into it when finite outside it,
// nothing when not finite (the reader warns and keeps its default).
[[nodiscard]] inline std::optional<float> readable_alpha(float value) noexcept {
    if (!std::isfinite(value)) return std::nullopt;
    return value < 0.0F ? 0.0F : (value > 1.0F ? 1.0F : value);
}

}  // namespace raster
