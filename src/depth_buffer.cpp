#include <raster/depth_buffer.hpp>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace raster {

void DepthBuffer::prepare(int width, int height) {
    if (width < 1 || height < 1) throw std::invalid_argument("depth buffer needs a positive size");
    width_ = width;
    height_ = height;
    depths_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    std::fill(depths_.begin(), depths_.end(), std::numeric_limits<float>::infinity());
}

float DepthBuffer::at(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) {
        throw std::out_of_range("depth (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the buffer");
    }
    return depths_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
}

}  // namespace raster
