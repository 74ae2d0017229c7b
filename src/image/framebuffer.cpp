#include <raster/image/framebuffer.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace raster {
namespace {

int checked_side(int side, const char* name) {
    if (side < 1 || side > kMaxImageSide) {
        throw std::invalid_argument(std::string("framebuffer ") + name + " must be 1.." +
                                    std::to_string(kMaxImageSide) + ", got " + std::to_string(side));
    }
    return side;
}

std::size_t offset_of(int x, int y, int width) {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
}

}  // namespace

Framebuffer::Framebuffer(int width, int height)
    : width_(checked_side(width, "width")), height_(checked_side(height, "height")),
      bytes_(offset_of(0, height_, width_), 0) {}

Framebuffer::Framebuffer(int width, int height, std::vector<std::uint8_t> rgb)
    : width_(checked_side(width, "width")), height_(checked_side(height, "height")), bytes_(std::move(rgb)) {
    if (bytes_.size() != offset_of(0, height_, width_)) {
        throw std::invalid_argument("framebuffer bytes do not match " + std::to_string(width_) + "x" +
                                    std::to_string(height_) + " RGB");
    }
}

void Framebuffer::set_pixel(int x, int y, Rgb colour) noexcept {
    if (!contains(x, y)) return;
    const std::size_t at = offset_of(x, y, width_);
    bytes_[at] = colour.r;
    bytes_[at + 1] = colour.g;
    bytes_[at + 2] = colour.b;
}

void Framebuffer::fill_row(int y, int x_begin, int x_end, Rgb colour) noexcept {
    if (y < 0 || y >= height_) return;
    x_begin = std::max(x_begin, 0);
    x_end = std::min(x_end, width_);
    if (x_begin >= x_end) return;  // empty, or wholly left or right of the buffer
    for (std::size_t at = offset_of(x_begin, y, width_), end = offset_of(x_end, y, width_); at < end; at += 3) {
        bytes_[at] = colour.r;
        bytes_[at + 1] = colour.g;
        bytes_[at + 2] = colour.b;
    }
}

Rgb Framebuffer::pixel(int x, int y) const {
    if (!contains(x, y)) {
        throw std::out_of_range("pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") is outside the framebuffer");
    }
    const std::size_t at = offset_of(x, y, width_);
    return {bytes_[at], bytes_[at + 1], bytes_[at + 2]};
}

void Framebuffer::clear(Rgb colour) noexcept { clear_rows(0, height_, colour); }

void Framebuffer::clear_rows(int y_begin, int y_end, Rgb colour) noexcept {
    y_begin = std::max(y_begin, 0);
    y_end = std::min(y_end, height_);
    if (y_begin >= y_end) return;
    // Paint one pixel, then keep doubling the painted prefix: memcpy speed for any colour.
    std::uint8_t* const first = bytes_.data() + offset_of(0, y_begin, width_);
    const std::size_t size = offset_of(0, y_end, width_) - offset_of(0, y_begin, width_);
    first[0] = colour.r;
    first[1] = colour.g;
    first[2] = colour.b;
    for (std::size_t done = 3; done < size; done *= 2) std::memcpy(first + done, first, std::min(done, size - done));
}

std::vector<std::uint8_t> rgba_bytes(const Framebuffer& image, std::span<const std::uint8_t> alpha) {
    const auto pixels = static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height());
    if (alpha.size() != pixels) {
        throw std::invalid_argument("alpha has " + std::to_string(alpha.size()) + " bytes for " +
                                    std::to_string(pixels) + " pixels");
    }
    std::vector<std::uint8_t> rgba(pixels * 4);
    const std::uint8_t* rgb = image.bytes().data();
    for (std::size_t i = 0; i < pixels; ++i) {
        rgba[i * 4] = rgb[i * 3];
        rgba[i * 4 + 1] = rgb[i * 3 + 1];
        rgba[i * 4 + 2] = rgb[i * 3 + 2];
        rgba[i * 4 + 3] = alpha[i];
    }
    return rgba;
}

}  // namespace raster
