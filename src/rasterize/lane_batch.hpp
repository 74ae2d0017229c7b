#pragma once

#include <raster/rasterize/framebuffer.hpp>
#include <raster/shade/lanes.hpp>

#include <array>
#include <cstdint>
#include <span>

// Pixels gathered for a shader that shades in lanes (raster/shade/lanes.hpp): the rasterizer
// adds each pixel that passed its depth test, and every kLanes pixels (and at the end of a
// triangle) the shader colours them all at once.
namespace raster::detail {

// A shader whose pixel stage also takes how its Varying changes per pixel step in x and in y:
// texture filtering chooses its mip level from that.
template <typename Shader>
concept NeedsFootprint = requires(const Shader& shader, const typename Shader::Varying& varying) {
    shader.pixel(varying, varying, varying);
};

// A shader that also colours kLanes pixels at once.
template <typename Shader>
concept LaneShader = requires(const Shader& shader, std::span<const typename Shader::Varying> varyings, std::span<Rgb> out) {
    shader.pixels(varyings, out);
} || requires(const Shader& shader, std::span<const typename Shader::Varying> varyings, std::span<Rgb> out) {
    shader.pixels(varyings, varyings, varyings, out);
};

// The Varying at a pixel and, for a shader that filters, its change per pixel step.
template <typename Varying>
struct PixelVarying {
    Varying value;
    Varying per_x{};
    Varying per_y{};
};

template <typename Shader>
class LaneBatch {
public:
    using Varying = typename Shader::Varying;
    explicit LaneBatch(const Shader& shader) noexcept : shader_(shader) {}

    // Queues a pixel whose colour goes to the samples of `out` set in `samples` (bit s: the
    // three bytes at out + 3 s); a one-sample pixel has samples 1.
    void add(std::uint8_t* out, std::uint32_t samples, const PixelVarying<Varying>& at) noexcept {
        const auto i = static_cast<std::size_t>(count_);
        out_[i] = out, samples_[i] = samples, values_[i] = at.value;
        if constexpr (NeedsFootprint<Shader>) per_x_[i] = at.per_x, per_y_[i] = at.per_y;
        if (++count_ == kLanes) flush();
    }

    // Shades and writes every queued pixel (none are queued for a shader without lanes).
    void flush() noexcept {
        if constexpr (LaneShader<Shader>) shade_queued();
    }

private:
    void shade_queued() noexcept {
        if (count_ == 0) return;
        const auto n = static_cast<std::size_t>(count_);
        std::array<Rgb, kLanes> colours{};
        const std::span<const Varying> values(values_.data(), n);
        if constexpr (NeedsFootprint<Shader>) {
            shader_.pixels(values, std::span<const Varying>(per_x_.data(), n), std::span<const Varying>(per_y_.data(), n), std::span(colours).first(n));
        } else {
            shader_.pixels(values, std::span(colours).first(n));
        }
        for (std::size_t i = 0; i < n; ++i) {
            const Rgb c = colours[i];
            for (std::uint32_t mask = samples_[i], s = 0; mask != 0; mask >>= 1U, ++s) {
                if ((mask & 1U) == 0) continue;
                std::uint8_t* out = out_[i] + s * 3;
                out[0] = c.r, out[1] = c.g, out[2] = c.b;
            }
        }
        count_ = 0;
    }

    const Shader& shader_;
    int count_ = 0;
    std::array<std::uint8_t*, kLanes> out_{};
    std::array<std::uint32_t, kLanes> samples_{};
    std::array<Varying, kLanes> values_{};
    std::array<Varying, kLanes> per_x_{};
    std::array<Varying, kLanes> per_y_{};
};

}  // namespace raster::detail
