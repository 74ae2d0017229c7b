#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/image/lanes.hpp>
#include <raster/rasterize/shader.hpp>

#include <array>
#include <cstdint>
#include <span>

// Pixels gathered for the shader: the rasterizers add each pixel that passed its depth test, and
// every kLanes pixels the shader colours them all at once (raster/image/lanes.hpp). A batch may
// stay open across triangles: pixels are written in the order they were added, so a later
// triangle's pixel still lands over an earlier one's.
namespace raster::detail {

// A shader that colours kLanes pixels at once; every shader of the library is one, and the
// batch runs any other (a test's, the lab's) pixel by pixel through pixel().
template <typename Shader>
concept LaneShader = requires(const Shader& shader, std::span<const typename Shader::Varying> varyings,
                              std::span<Rgb> out) {
    shader.pixels(varyings, out);
}
|| requires(const Shader& shader, std::span<const typename Shader::Varying> varyings, std::span<Rgb> out) {
    shader.pixels(varyings, varyings, varyings, out);
};

// The Varying at a pixel and, for a shader that filters, its change per pixel step.
template <typename Varying>
struct PixelVarying {
    Varying value;
    Varying per_x{};
    Varying per_y{};
};

// Writes colour `c` to the samples of `out` set in `samples` (bit s: the three bytes at out + 3 s).
inline void write_samples(std::uint8_t* out, std::uint32_t samples, Rgb c) noexcept {
    for (std::uint32_t s = 0; samples != 0; samples >>= 1U, ++s) {
        if ((samples & 1U) == 0) continue;
        out[s * 3] = c.r, out[s * 3 + 1] = c.g, out[s * 3 + 2] = c.b;
    }
}

template <typename Shader>
class LaneBatch {
public:
    using Varying = typename Shader::Varying;
    explicit LaneBatch(const Shader& shader) noexcept : shader_(shader) {}

    // Queues a pixel whose colour goes to the samples of `out` set in `samples`; a one-sample
    // pixel has samples 1.
    void add(std::uint8_t* out, std::uint32_t samples, const PixelVarying<Varying>& at) noexcept {
        const auto i = static_cast<std::size_t>(count_);
        out_[i] = out, samples_[i] = samples, values_[i] = at.value;
        if constexpr (NeedsFootprint<Shader>) footprint_.per_x[i] = at.per_x, footprint_.per_y[i] = at.per_y;
        if (++count_ == kLanes) flush();
    }

    // Shades and writes every queued pixel.
    void flush() noexcept {
        if (count_ == 0) return;
        const auto n = static_cast<std::size_t>(count_);
        std::array<Rgb, kLanes> colours{};
        const std::span<const Varying> values(values_.data(), n);
        if constexpr (!LaneShader<Shader>) {
            for (std::size_t i = 0; i < n; ++i) {
                if constexpr (NeedsFootprint<Shader>) {
                    colours[i] = shader_.pixel(values_[i], footprint_.per_x[i], footprint_.per_y[i]);
                } else {
                    colours[i] = shader_.pixel(values_[i]);
                }
            }
        } else if constexpr (NeedsFootprint<Shader>) {
            shader_.pixels(values, std::span<const Varying>(footprint_.per_x.data(), n),
                           std::span<const Varying>(footprint_.per_y.data(), n), std::span(colours).first(n));
        } else {
            shader_.pixels(values, std::span(colours).first(n));
        }
        for (std::size_t i = 0; i < n; ++i) write_samples(out_[i], samples_[i], colours[i]);
        count_ = 0;
    }

private:
    struct Footprint {
        std::array<Varying, kLanes> per_x{};
        std::array<Varying, kLanes> per_y{};
    };
    struct NoFootprint {};

    const Shader& shader_;
    int count_ = 0;
    std::array<std::uint8_t*, kLanes> out_{};
    std::array<std::uint32_t, kLanes> samples_{};
    std::array<Varying, kLanes> values_{};
    [[no_unique_address]] std::conditional_t<NeedsFootprint<Shader>, Footprint, NoFootprint> footprint_{};
};

}  // namespace raster::detail
