#include <raster/rasterize/depth_buffer.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace raster {

void DepthBuffer::prepare(int width, int height) {
    resize(width, height);
    clear_rows(0, height);
}

void DepthBuffer::resize(int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("depth buffer needs a positive size");
    width_ = width;
    height_ = height;
    depths_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    stale_.resize(static_cast<std::size_t>(height));
}

void DepthBuffer::clear_rows(int y_begin, int y_end) noexcept {
    y_begin = std::max(y_begin, 0);
    y_end = std::min(y_end, height_);
    if (y_begin >= y_end) return;
    std::fill(stale_.begin() + y_begin, stale_.begin() + y_end, static_cast<unsigned char>(1));
}

void DepthBuffer::fill_row(int y, float* start) noexcept {
    std::fill(start, start + width_, std::numeric_limits<float>::infinity());
    stale_[static_cast<std::size_t>(y)] = 0;
}

float DepthBuffer::at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) {
        throw std::out_of_range("depth (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the buffer");
    }
    if (stale_[static_cast<std::size_t>(y)] != 0)
        return std::numeric_limits<float>::infinity();  // cleared, not yet filled
    return depths_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
}

std::vector<std::uint8_t> DepthBuffer::coverage() const {
    std::vector<std::uint8_t> alpha(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0);
    for (int y = 0; y < height_; ++y) {
        if (stale_[static_cast<std::size_t>(y)] != 0) continue;  // cleared and never drawn on
        const std::size_t start = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
        for (std::size_t x = 0; x < static_cast<std::size_t>(width_); ++x) {
            alpha[start + x] = std::isinf(depths_[start + x]) ? 0 : 255;
        }
    }
    return alpha;
}

}  // namespace raster
