#pragma once

#include <vector>

namespace raster {

// One float per pixel: the view depth (distance in front of the eye) of the nearest surface
// drawn so far. Holds no memory until a scene that needs it prepares it
// (doc/conventions.md#depth).
class DepthBuffer {
public:
    // Sizes the buffer (allocating only if the size changed) and sets every depth to +infinity.
    void prepare(int width, int height);

    [[nodiscard]] bool allocated() const noexcept { return !depths_.empty(); }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

    // Row y, width() entries; valid after prepare().
    [[nodiscard]] float* row(int y) noexcept { return depths_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_); }
    // Throws std::out_of_range outside the buffer.
    [[nodiscard]] float at(int x, int y) const;

private:
    int width_ = 0;
    int height_ = 0;
    std::vector<float> depths_;
};

}  // namespace raster
