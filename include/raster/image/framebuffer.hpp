#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace raster {

// An 8-bit-per-channel colour; see doc/conventions.md#colour.
struct Rgb {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;

    friend constexpr bool operator==(Rgb, Rgb) = default;
};

// The largest width or height a Framebuffer (and a WebP file) may have.
inline constexpr int kMaxImageSide = 16383;

// A width x height grid of Rgb pixels, row-major, (0, 0) at the top left, black when made.
class Framebuffer {
public:
    // Throws std::invalid_argument unless 1 <= width, height <= kMaxImageSide.
    Framebuffer(int width, int height);
    // Adopts packed RGB bytes (see bytes()); throws std::invalid_argument if the size is wrong.
    Framebuffer(int width, int height, std::vector<std::uint8_t> rgb);

    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }
    [[nodiscard]] bool contains(int x, int y) const noexcept { return x >= 0 && y >= 0 && x < width_ && y < height_; }

    // Writes one pixel; a write outside the buffer is skipped, so primitives need no clipping.
    void set_pixel(int x, int y, Rgb colour) noexcept;
    // Paints pixels [x_begin, x_end) of row y, skipping the part outside the buffer.
    void fill_row(int y, int x_begin, int x_end, Rgb colour) noexcept;
    // Throws std::out_of_range outside the buffer.
    [[nodiscard]] Rgb pixel(int x, int y) const;
    void clear(Rgb colour) noexcept;
    // Paints rows [y_begin, y_end) whole, at memcpy speed; rows outside the buffer are skipped.
    void clear_rows(int y_begin, int y_end, Rgb colour) noexcept;

    // Packed R, G, B bytes, row after row with no padding.
    [[nodiscard]] std::span<const std::uint8_t> bytes() const noexcept { return bytes_; }
    // The same bytes for primitives that write whole spans; they must stay inside the buffer.
    [[nodiscard]] std::uint8_t* pixels() noexcept { return bytes_.data(); }

    friend bool operator==(const Framebuffer&, const Framebuffer&) = default;

private:
    int width_;
    int height_;
    std::vector<std::uint8_t> bytes_;
};

// Packed R, G, B, A bytes: the picture with `alpha` (one byte per pixel, row-major, 255 opaque)
// woven in. Throws std::invalid_argument unless `alpha` holds one byte per pixel.
[[nodiscard]] std::vector<std::uint8_t> rgba_bytes(const Framebuffer& image, std::span<const std::uint8_t> alpha);

}  // namespace raster
