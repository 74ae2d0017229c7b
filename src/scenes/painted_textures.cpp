#include "scenes/painted_textures.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace raster::detail {

float grain(int x, int y, std::uint32_t seed) {
    std::uint32_t h =
        static_cast<std::uint32_t>(x) * 374761393U + static_cast<std::uint32_t>(y) * 668265263U + seed * 2246822519U;
    h = (h ^ (h >> 13)) * 1274126177U;
    return static_cast<float>((h ^ (h >> 16)) & 0xFFFFU) / 65536.0F;
}

Rgb shaded(Rgb base, float k) {
    const auto c = [k](std::uint8_t v) {
        return static_cast<std::uint8_t>(std::clamp(static_cast<float>(v) * k, 0.0F, 255.0F));
    };
    return {c(base.r), c(base.g), c(base.b)};
}

std::shared_ptr<const Texture> painted(int width, int height, const std::function<Rgb(int, int)>& paint) {
    Framebuffer image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) image.set_pixel(x, y, paint(x, y));
    }
    return std::make_shared<const Texture>(std::move(image));
}

std::shared_ptr<const Texture> scales() {
    return painted(64, 64, [](int x, int y) {
        const int row = y / 16, shifted = x + (row % 2) * 8;
        const float dx = static_cast<float>(shifted % 16) - 7.5F, dy = static_cast<float>(y % 16) - 2.0F;
        const float d = std::min(1.0F, std::sqrt(dx * dx + dy * dy) / 14.0F);
        const Rgb gold{214, 168, 58}, green{24, 96, 70};
        const auto mix = [d](std::uint8_t a, std::uint8_t b) { return static_cast<std::uint8_t>(a + (b - a) * d); };
        return Rgb{mix(gold.r, green.r), mix(gold.g, green.g), mix(gold.b, green.b)};
    });
}

std::shared_ptr<const Texture> speckled(Rgb base, float spread, std::uint32_t seed) {
    return painted(64, 64,
                   [=](int x, int y) { return shaded(base, 1.0F - spread + 2.0F * spread * grain(x, y, seed)); });
}

std::shared_ptr<const Texture> bricks() {
    return painted(64, 64, [](int x, int y) {
        const int row = y / 8, shifted = x + (row % 2) * 8;
        if (y % 8 == 7 || shifted % 16 == 15) return Rgb{196, 192, 180};
        return shaded({168, 72, 50}, 0.85F + 0.3F * grain(shifted / 16, row, 7));
    });
}

std::shared_ptr<const Texture> planks(Rgb base, int width) {
    return painted(64, 64, [=](int x, int y) {
        if (y % width == width - 1) return shaded(base, 0.55F);
        return shaded(base, 0.85F + 0.25F * grain(x / 8, y / width, 3) + 0.05F * grain(x, y, 4));
    });
}

std::shared_ptr<const Texture> waves() {
    return painted(64, 64, [](int x, int y) {
        const double crest = std::sin((x + 6.0 * std::sin(y * 0.3)) * 0.35);
        return shaded({34, 86, 160}, static_cast<float>(0.9 + 0.25 * crest * crest * crest) + 0.06F * grain(x, y, 9));
    });
}

std::shared_ptr<const Texture> sail() {
    return painted(64, 64, [](int x, int y) {
        return (y / 8) % 3 == 1 ? Rgb{200, 40, 40} : shaded({236, 232, 220}, 0.95F + 0.05F * grain(x, y, 5));
    });
}

std::shared_ptr<const Texture> streaks() {
    return painted(64, 64, [](int x, int y) {
        // Each column its own streak; foam where a column's phase peaks, so the fall reads as moving.
        const float phase = grain(x, 0, 11) * 64.0F;
        const float foam = 0.5F + 0.5F * static_cast<float>(std::sin((static_cast<float>(y) + phase) * 0.196F));
        const Rgb water{70, 140, 200}, white{226, 240, 250};
        const float k = foam * foam * foam * (0.6F + 0.4F * grain(x, y / 4, 12));
        const auto mix = [k](std::uint8_t a, std::uint8_t b) { return static_cast<std::uint8_t>(a + (b - a) * k); };
        return Rgb{mix(water.r, white.r), mix(water.g, white.g), mix(water.b, white.b)};
    });
}

std::shared_ptr<const Texture> runway() {
    return painted(64, 64, [](int x, int y) {
        if (x < 2 || x > 61) return Rgb{230, 230, 224};
        if (x >= 30 && x <= 33 && y < 32) return Rgb{236, 236, 230};
        return shaded({70, 72, 76}, 0.85F + 0.3F * grain(x, y, 13));
    });
}

std::shared_ptr<const Texture> corrugated() {
    return painted(64, 64, [](int x, int y) {
        const double rib = std::cos(x * 2.0 * 3.14159265358979 / 8.0);
        return shaded({150, 156, 162}, static_cast<float>(0.85 + 0.15 * rib) + 0.04F * grain(x, y, 14));
    });
}

std::shared_ptr<const Texture> livery() {
    return painted(64, 64, [](int x, int y) {
        if (y >= 26 && y < 38) return Rgb{190, 34, 40};
        return shaded({238, 238, 232}, 0.96F + 0.04F * grain(x, y, 15));
    });
}

std::shared_ptr<const Texture> windows() {
    return painted(64, 64, [](int x, int y) {
        if (x % 32 < 4 || y % 32 < 4) return Rgb{236, 232, 220};
        return shaded({40, 70, 110}, 0.8F + 0.4F * static_cast<float>((x % 32 + y % 32) % 28) / 28.0F);
    });
}

}  // namespace raster::detail
