#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

// Multisampling's target: every pixel's samples side by side, each an sRGB colour and a view
// depth, resolved in linear light into a framebuffer strip by strip (doc/conventions.md#samples).
// A clear marks pixels untouched instead of writing their samples; a pixel's samples are filled
// the first time a triangle reaches it, so a frame pays per pixel drawn, not per sample shown.
namespace raster::detail {

class SampleBuffer {
public:
    // Keeps its memory when the size does not grow; the contents are undefined until cleared.
    // `background` is what every sample shows until a triangle reaches its pixel: set here, once
    // a frame, before any thread clears or draws.
    void resize(int width, int height, int samples, Rgb background);
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }
    [[nodiscard]] int samples() const noexcept { return samples_; }

    // Rows [y_begin, y_end): every sample the background, at infinite depth.
    void clear_rows(int y_begin, int y_end) noexcept;
    // The samples of pixel (x, y): samples() colours of three bytes, and samples() depths, which
    // `touch` fills (with the clear's values) when the pixel is first drawn after a clear.
    void touch(int x, int y) noexcept {
        std::uint8_t& touched =
            touched_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
        if (touched == 0) fill(index(x, y)), touched = 1;
    }
    // Asks the cache for pixel (x, y)'s samples ahead of their use: small items in a strip reach
    // its pixels in no order, and each would otherwise wait on memory.
    void prefetch(int x, int y) const noexcept {
        const std::size_t pixel =
            static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
        __builtin_prefetch(touched_.data() + pixel);
        __builtin_prefetch(depths_.data() + index(x, y));
        __builtin_prefetch(colours_.data() + index(x, y) * 3);
    }
    [[nodiscard]] std::uint8_t* colours(int x, int y) noexcept { return colours_.data() + index(x, y) * 3; }
    [[nodiscard]] float* depths(int x, int y) noexcept { return depths_.data() + index(x, y); }

    // Rows [y_begin, y_end) of `frame`, each pixel the linear mean of its samples. With `alpha`
    // (one byte per pixel of the frame), the mean of the samples a surface covers (finite
    // depth), the background where none does, and their share as alpha, 0..255.
    void resolve_rows(int y_begin, int y_end, Framebuffer& frame, Rgb background, std::uint8_t* alpha) const noexcept;

private:
    [[nodiscard]] std::size_t index(int x, int y) const noexcept {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) *
               static_cast<std::size_t>(samples_);
    }

    void fill(std::size_t first) noexcept;

    int width_ = 0;
    int height_ = 0;
    int samples_ = 1;
    std::vector<std::uint8_t> colours_;
    std::vector<float> depths_;
    std::vector<std::uint8_t> touched_;  // per pixel: 1 once its samples hold this frame's values
    Rgb background_{};
};

}  // namespace raster::detail
