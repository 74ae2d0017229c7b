#pragma once

#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/image/lanes.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>
#include <glm/vec2.hpp>

// Colour textures: sRGB texels decoded to linear light before they are filtered, as a GPU's
// SRGB8 formats do, with a mip chain averaged in linear light (doc/conventions.md#textures);
// data maps (normals, metal and roughness, occlusion) read their bytes as they are, byte / 255.
namespace raster {

// What happens outside [0, 1]: the image tiles, or its edge texels stretch on.
enum class TextureWrap { repeat, clamp };
// How texels become a colour: the texel under the point, a blend of the four nearest, or that
// blend on the two mip levels whose texel size is nearest the pixel's footprint, blended again.
enum class TextureFilter { nearest, bilinear, trilinear };

// How a texel's bytes stand for values: sRGB-encoded colour, or linear data (byte / 255).
enum class TexelEncoding { srgb, linear };

struct Sampler {
    TextureFilter filter = TextureFilter::trilinear;
    TextureWrap wrap = TextureWrap::repeat;
};

// How texture coordinates change from one pixel to the next, in u and v per pixel; trilinear
// filtering picks its mip level from it, the other filters ignore it.
struct UvFootprint {
    glm::vec2 per_pixel_x{0.0F};
    glm::vec2 per_pixel_y{0.0F};
};

// kLanes texture coordinates and their footprints (UvFootprint), one array per component.
struct LaneUvs {
    LaneFloats u{}, v{};
    LaneFloats u_per_x{}, v_per_x{};
    LaneFloats u_per_y{}, v_per_y{};
};

// An image read as a texture; u runs left to right and v bottom to top, as in OBJ and OpenGL,
// so (0, 0) is the bottom-left corner of the image and texel centres sit at (i + ½) / width.
class Texture {
public:
    // Adopts an image whose row 0 is its top row, its bytes sRGB-encoded; builds the mip chain.
    explicit Texture(Framebuffer image, TexelEncoding encoding = TexelEncoding::srgb);
    // The same with the image's alpha, one byte a texel in the same order: kept only where some
    // texel is below 255, so that an opaque texture pays nothing (doc/conventions.md#transparency).
    Texture(Framebuffer image, std::vector<std::uint8_t> alpha);
    // Adopts a whole mip chain as level() gives one (each level half the one before, at least 1,
    // down to 1 x 1), so that a chain built elsewhere is not built again; throws
    // std::invalid_argument for any other chain.
    // `alpha`: level 0's alpha plane as alpha_plane() gives it (empty: none).
    [[nodiscard]] static Texture from_levels(std::vector<Framebuffer> levels,
                                             TexelEncoding encoding = TexelEncoding::srgb,
                                             std::vector<std::uint8_t> alpha = {});
    [[nodiscard]] TexelEncoding encoding() const noexcept { return encoding_; }

    [[nodiscard]] int width() const noexcept { return levels_.front().width(); }
    [[nodiscard]] int height() const noexcept { return levels_.front().height(); }
    // Level 0 is the image; each next level halves both sides (at least 1) down to 1 x 1.
    [[nodiscard]] std::size_t level_count() const noexcept { return levels_.size(); }
    [[nodiscard]] const Framebuffer& level(std::size_t index) const { return levels_.at(index); }
    [[nodiscard]] bool has_alpha() const noexcept { return !alpha_.empty(); }
    [[nodiscard]] const std::vector<std::uint8_t>& alpha_plane() const noexcept { return alpha_; }
    // The alpha of the image's texel under (u, v), 0..1; 1 for a texture without alpha.
    [[nodiscard]] float alpha(glm::vec2 uv, TextureWrap wrap) const noexcept;

    // The colour at (u, v) in linear light; never NaN, whatever u and v are.
    [[nodiscard]] LinearRgb sample(glm::vec2 uv, const UvFootprint& footprint, Sampler sampler) const noexcept;
    // sample() at `count` points at once: the arithmetic in SIMD lanes, the texel reads lane by
    // lane, each lane equal to sample() bit for bit.
    void sample_lanes(const LaneUvs& at, Sampler sampler, LaneRgb& out, int count) const noexcept;

private:
    explicit Texture(TexelEncoding encoding) noexcept;
    [[nodiscard]] LinearRgb texel(const Framebuffer& level, int x, int y) const noexcept;
    [[nodiscard]] LinearRgb nearest(const Framebuffer& level, glm::vec2 uv, TextureWrap wrap) const noexcept;
    [[nodiscard]] LinearRgb bilinear(const Framebuffer& level, glm::vec2 uv, TextureWrap wrap) const noexcept;
    // bilinear() in lanes, lane i reading level(levels[i]).
    void bilinear_lanes(const std::array<std::size_t, kLanes>& levels, const LaneFloats& u, const LaneFloats& v,
                        TextureWrap wrap, LaneRgb& out, int count) const noexcept;

    std::vector<Framebuffer> levels_;
    std::array<float, 256> linear_from_byte_{};
    std::vector<std::uint8_t> alpha_;  // of level 0; empty when every texel is opaque
    TexelEncoding encoding_ = TexelEncoding::srgb;
};

}  // namespace raster
