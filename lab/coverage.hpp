#pragma once

#include <raster/rasterize/fill.hpp>

#include <cstdint>
#include <vector>

namespace lab {

using raster::PixelRect;

// How many times each pixel of a rectangle was hit: the target every lab fill method draws into,
// so double hits and cracks can be counted.
class Coverage {
public:
    explicit Coverage(PixelRect rect);

    [[nodiscard]] const PixelRect& rect() const { return rect_; }
    [[nodiscard]] bool contains(std::int64_t x, std::int64_t y) const {
        return x >= rect_.x && y >= rect_.y && x < std::int64_t{rect_.x} + rect_.width &&
               y < std::int64_t{rect_.y} + rect_.height;
    }
    void hit(std::int64_t x, std::int64_t y) {
        if (contains(x, y)) ++counts_[index(x, y)];
    }
    // Hits [x_begin, x_end) of row y, clipped to the rectangle.
    void hit_row(std::int64_t y, std::int64_t x_begin, std::int64_t x_end);
    [[nodiscard]] int at(std::int64_t x, std::int64_t y) const { return counts_[index(x, y)]; }
    [[nodiscard]] std::int64_t total() const;
    void clear();

private:
    [[nodiscard]] std::size_t index(std::int64_t x, std::int64_t y) const {
        return static_cast<std::size_t>((y - rect_.y) * rect_.width + (x - rect_.x));
    }
    PixelRect rect_;
    std::vector<std::uint16_t> counts_;
};

}  // namespace lab
