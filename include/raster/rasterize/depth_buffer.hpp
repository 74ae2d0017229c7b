#pragma once

#include <cstdint>
#include <vector>

namespace raster {

// One float per pixel: the view depth (distance in front of the eye) of the nearest surface
// drawn so far. Holds no memory until a scene that needs it prepares it
// (doc/conventions.md#depth).
class DepthBuffer {
public:
    // Sizes the buffer (allocating only if the size changed) and sets every depth to +infinity.
    void prepare(int width, int height);
    // The same in two steps, for a render split into bands of rows: the size first, then each
    // band clears its own rows to +infinity. A cleared row is only marked: it is filled when
    // first drawn on, so rows the scene never reaches cost nothing.
    void resize(int width, int height);
    void clear_rows(int y_begin, int y_end) noexcept;

    [[nodiscard]] bool allocated() const noexcept { return !depths_.empty(); }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

    // Row y, width() entries, for reading and writing; valid after prepare().
    [[nodiscard]] float* row(int y) noexcept {
        float* const start = depths_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
        if (stale_[static_cast<std::size_t>(y)] != 0) fill_row(y, start);
        return start;
    }
    // Throws std::out_of_range outside the buffer.
    [[nodiscard]] float at(int x, int y) const;
    // One byte per pixel, row-major: 255 where a surface was drawn, 0 where nothing was: the
    // alpha of a picture on a transparent background.
    [[nodiscard]] std::vector<std::uint8_t> coverage() const;

private:
    void fill_row(int y, float* start) noexcept;

    int width_ = 0;
    int height_ = 0;
    std::vector<float> depths_;
    std::vector<unsigned char> stale_;  // per row: cleared, but not yet filled with +infinity
};

}  // namespace raster
