#include "rasterize/sample_buffer.hpp"

#include <raster/image/colour.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>

namespace raster::detail {

void SampleBuffer::resize(int width, int height, int samples, Rgb background) {
    width_ = width, height_ = height, samples_ = samples, background_ = background;
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    const std::size_t count = pixels * static_cast<std::size_t>(samples);
    colours_.resize(count * 3);
    depths_.resize(count);
    touched_.resize(pixels);
}

void SampleBuffer::clear_rows(int y_begin, int y_end) noexcept {
    y_begin = std::max(y_begin, 0), y_end = std::min(y_end, height_);
    if (y_begin >= y_end) return;
    const auto row = [&](int y) { return touched_.begin() + static_cast<std::ptrdiff_t>(y) * width_; };
    std::fill(row(y_begin), row(y_end), std::uint8_t{0});
}

void SampleBuffer::fill(std::size_t first) noexcept {
    std::uint8_t* colour = colours_.data() + first * 3;
    for (int s = 0; s < samples_; ++s, colour += 3)
        colour[0] = background_.r, colour[1] = background_.g, colour[2] = background_.b;
    std::fill_n(depths_.begin() + static_cast<std::ptrdiff_t>(first), samples_, std::numeric_limits<float>::infinity());
}

void SampleBuffer::resolve_rows(int y_begin, int y_end, Framebuffer& frame, Rgb background,
                                std::uint8_t* alpha) const noexcept {
    std::uint8_t* out = frame.pixels();
    const auto n = static_cast<std::size_t>(samples_);
    const std::array<float, 256>& linear = linear_from_srgb_bytes();
    for (int y = std::max(y_begin, 0); y < std::min(y_end, height_); ++y) {
        for (int x = 0; x < width_; ++x) {
            const std::size_t first = index(x, y);
            const std::size_t pixel =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
            std::uint8_t* written = out + pixel * 3;
            if (touched_[pixel] == 0) {  // nothing drew here: the background, uncovered
                written[0] = background.r, written[1] = background.g, written[2] = background.b;
                if (alpha != nullptr) alpha[pixel] = 0;
                continue;
            }
            const std::uint8_t* own = colours_.data() + first * 3;
            // Inside a surface every sample holds the same colour: it is the pixel's, exactly.
            // The bytes repeat with period 3 exactly when every sample equals the first.
            bool same = std::memcmp(own + 3, own, (n - 1) * 3) == 0;
            for (std::size_t s = 0; s < n && same && alpha != nullptr; ++s) same = !std::isinf(depths_[first + s]);
            if (same) {
                written[0] = own[0], written[1] = own[1], written[2] = own[2];
                if (alpha != nullptr) alpha[pixel] = 255;
                continue;
            }
            float sum[3] = {0.0F, 0.0F, 0.0F};
            std::size_t counted = 0;
            for (std::size_t s = 0; s < n; ++s) {
                if (alpha != nullptr && std::isinf(depths_[first + s])) continue;  // the background shows through
                for (std::size_t c = 0; c < 3; ++c) sum[c] += linear[colours_[(first + s) * 3 + c]];
                ++counted;
            }
            if (counted == 0) {
                written[0] = background.r, written[1] = background.g, written[2] = background.b;
            } else {
                const float share = 1.0F / static_cast<float>(counted);
                for (std::size_t c = 0; c < 3; ++c) written[c] = srgb_byte_from_linear(sum[c] * share);
            }
            if (alpha != nullptr) alpha[pixel] = static_cast<std::uint8_t>((counted * 255 + n / 2) / n);
        }
    }
}

}  // namespace raster::detail
