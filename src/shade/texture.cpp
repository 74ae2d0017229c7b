#include <raster/shade/texture.hpp>

#include "shade/texture_wrap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <glm/geometric.hpp>

namespace raster {

namespace {

using detail::wrapped;
using detail::wrapped_index;

// The next mip level: each texel the mean, in linear light, of the 2 x 2 texels it covers (one
// row or column where a side is already 1 texel); an odd side's last row or column is left out,
// as a plain box filter does.
Framebuffer halved(const Framebuffer& level, const std::array<float, 256>& linear, TexelEncoding encoding) {
    const int width = std::max(1, level.width() / 2), height = std::max(1, level.height() / 2);
    Framebuffer next(width, height);
    const std::uint8_t* in = level.bytes().data();
    std::uint8_t* out = next.pixels();
    const auto row_bytes = static_cast<std::size_t>(level.width()) * 3;
    for (int y = 0; y < height; ++y) {
        const int y0 = std::min(2 * y, level.height() - 1), y1 = std::min(2 * y + 1, level.height() - 1);
        for (int x = 0; x < width; ++x) {
            const int x0 = std::min(2 * x, level.width() - 1), x1 = std::min(2 * x + 1, level.width() - 1);
            for (std::size_t c = 0; c < 3; ++c) {
                const auto at = [&](int i, int j) {
                    return linear[in[static_cast<std::size_t>(j) * row_bytes + static_cast<std::size_t>(i) * 3 + c]];
                };
                const float mean = (at(x0, y0) + at(x1, y0) + at(x0, y1) + at(x1, y1)) * 0.25F;
                *out++ = encoding == TexelEncoding::srgb
                             ? srgb_byte_from_linear(mean)
                             : static_cast<std::uint8_t>(std::lround(std::clamp(mean, 0.0F, 1.0F) * 255.0F));
            }
        }
    }
    return next;
}

}  // namespace

Texture::Texture(TexelEncoding encoding) noexcept : encoding_(encoding) {
    for (std::size_t i = 0; i < linear_from_byte_.size(); ++i) {
        const double byte = static_cast<double>(i) / 255.0;
        linear_from_byte_[i] =
            static_cast<float>(encoding == TexelEncoding::srgb ? linear_from_srgb_channel(byte) : byte);
    }
}

Texture::Texture(Framebuffer image, TexelEncoding encoding) : Texture(encoding) {
    levels_.push_back(std::move(image));
    while (levels_.back().width() > 1 || levels_.back().height() > 1)
        levels_.push_back(halved(levels_.back(), linear_from_byte_, encoding_));
}

Texture::Texture(Framebuffer image, std::vector<std::uint8_t> alpha) : Texture(std::move(image)) {
    const std::size_t texels = static_cast<std::size_t>(width()) * static_cast<std::size_t>(height());
    if (alpha.size() != texels) throw std::invalid_argument("an alpha plane differs in size from its image");
    if (std::any_of(alpha.begin(), alpha.end(), [](std::uint8_t a) { return a != 255; })) alpha_ = std::move(alpha);
}

float Texture::alpha(glm::vec2 uv, TextureWrap wrap) const noexcept {
    if (alpha_.empty()) return 1.0F;
    const int w = width(), h = height();
    const float u = wrapped(uv.x, wrap), v = wrapped(uv.y, wrap);
    const int x = std::min(static_cast<int>(u * static_cast<float>(w)), w - 1);
    const int y = std::min(static_cast<int>((1.0F - v) * static_cast<float>(h)), h - 1);  // row 0 at v = 1
    return static_cast<float>(
               alpha_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)]) /
           255.0F;
}

Texture Texture::from_levels(std::vector<Framebuffer> levels, TexelEncoding encoding, std::vector<std::uint8_t> alpha) {
    for (std::size_t i = 1; i < levels.size(); ++i) {
        if (levels[i].width() != std::max(1, levels[i - 1].width() / 2) ||
            levels[i].height() != std::max(1, levels[i - 1].height() / 2)) {
            throw std::invalid_argument("a mip level is not half the one before it");
        }
    }
    if (levels.empty() || levels.back().width() != 1 || levels.back().height() != 1)
        throw std::invalid_argument("a mip chain must end at 1 x 1");
    Texture texture(encoding);
    texture.levels_ = std::move(levels);
    const std::size_t texels = static_cast<std::size_t>(texture.width()) * static_cast<std::size_t>(texture.height());
    if (!alpha.empty() && alpha.size() != texels)
        throw std::invalid_argument("an alpha plane differs in size from its image");
    texture.alpha_ = std::move(alpha);
    return texture;
}

LinearRgb Texture::texel(const Framebuffer& level, int x, int y) const noexcept {
    const std::uint8_t* p =
        level.bytes().data() +
        (static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width()) + static_cast<std::size_t>(x)) * 3;
    return {linear_from_byte_[p[0]], linear_from_byte_[p[1]], linear_from_byte_[p[2]]};
}

LinearRgb Texture::nearest(const Framebuffer& level, glm::vec2 uv, TextureWrap wrap) const noexcept {
    const int w = level.width(), h = level.height();
    const float u = wrapped(uv.x, wrap), v = wrapped(uv.y, wrap);
    // Row 0 is the top of the image, where v = 1.
    const int x = std::min(static_cast<int>(u * static_cast<float>(w)), w - 1);
    const int y = std::min(static_cast<int>((1.0F - v) * static_cast<float>(h)), h - 1);
    return texel(level, x, y);
}

LinearRgb Texture::bilinear(const Framebuffer& level, glm::vec2 uv, TextureWrap wrap) const noexcept {
    const int w = level.width(), h = level.height();
    // Texel centres sit at half-integers, so the four around the point start half a texel back.
    const float x = wrapped(uv.x, wrap) * static_cast<float>(w) - 0.5F;
    const float y = (1.0F - wrapped(uv.y, wrap)) * static_cast<float>(h) - 0.5F;
    const float x_floor = std::floor(x), y_floor = std::floor(y);
    const float fx = x - x_floor, fy = y - y_floor;
    const int x0 = static_cast<int>(x_floor), y0 = static_cast<int>(y_floor);
    const int xa = wrapped_index(x0, w, wrap), xb = wrapped_index(x0 + 1, w, wrap);
    const int ya = wrapped_index(y0, h, wrap), yb = wrapped_index(y0 + 1, h, wrap);
    const LinearRgb top = texel(level, xa, ya) * (1.0F - fx) + texel(level, xb, ya) * fx;
    const LinearRgb bottom = texel(level, xa, yb) * (1.0F - fx) + texel(level, xb, yb) * fx;
    return top * (1.0F - fy) + bottom * fy;
}

LinearRgb Texture::sample(glm::vec2 uv, const UvFootprint& footprint, Sampler sampler) const noexcept {
    const Framebuffer& base = levels_.front();
    if (sampler.filter == TextureFilter::nearest) return nearest(base, uv, sampler.wrap);
    if (sampler.filter == TextureFilter::bilinear || levels_.size() == 1) return bilinear(base, uv, sampler.wrap);
    // OpenGL's level of detail: log2 of the longer of the pixel's two steps, measured in texels.
    const glm::vec2 size(static_cast<float>(base.width()), static_cast<float>(base.height()));
    const float rho = std::max(glm::length(footprint.per_pixel_x * size), glm::length(footprint.per_pixel_y * size));
    const float lod = std::log2(rho);
    if (!(lod > 0.0F)) return bilinear(base, uv, sampler.wrap);  // magnified, or no footprint at all (NaN)
    const auto last = static_cast<float>(levels_.size() - 1);
    if (lod >= last) return bilinear(levels_.back(), uv, sampler.wrap);
    const float lower = std::floor(lod), blend = lod - lower;
    const auto index = static_cast<std::size_t>(lower);
    return bilinear(levels_[index], uv, sampler.wrap) * (1.0F - blend) +
           bilinear(levels_[index + 1], uv, sampler.wrap) * blend;
}

}  // namespace raster
