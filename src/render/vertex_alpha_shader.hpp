#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/image/lanes.hpp>
#include <raster/rasterize/shader.hpp>

#include "rasterize/lane_batch.hpp"

#include <array>
#include <cstddef>
#include <span>

// A shader with the corners' vertex alpha interpolated beside its own Varying
// (doc/conventions.md#vertex-alpha): the colour is the wrapped shader's, the alpha is read by the
// blend and the mask alone. Only objects that blend or mask by vertex alpha are drawn through it,
// so every other object's Varying stays as small as it was.
namespace raster::detail {

template <typename Inner>
struct VertexAlphaShader {
    struct Varying {
        typename Inner::Varying inner{};
        float alpha = 1.0F;
        friend Varying operator+(const Varying& x, const Varying& y) noexcept {
            return {x.inner + y.inner, x.alpha + y.alpha};
        }
        friend Varying operator-(const Varying& x, const Varying& y) noexcept {
            return {x.inner - y.inner, x.alpha - y.alpha};
        }
        friend Varying operator*(const Varying& x, float k) noexcept { return {x.inner * k, x.alpha * k}; }
    };
    static constexpr bool kFacetNormal = Inner::kFacetNormal;
    Inner inner;

    [[nodiscard]] Varying vertex(const Corner& corner) const noexcept { return {inner.vertex(corner), corner.alpha}; }
    [[nodiscard]] Rgb pixel(const Varying& v) const noexcept requires PlainPixelStage<Inner> {
        return inner.pixel(v.inner);
    }
    [[nodiscard]] Rgb pixel(const Varying& v, const Varying& per_x,
                            const Varying& per_y) const noexcept requires NeedsFootprint<Inner> {
        return inner.pixel(v.inner, per_x.inner, per_y.inner);
    }
    // pixels() as the wrapped shader has it, its Varyings copied out of these (up to kLanes).
    void pixels(std::span<const Varying> v, std::span<Rgb> out) const noexcept
        requires(LaneShader<Inner> && !NeedsFootprint<Inner>) {
        std::array<typename Inner::Varying, kLanes> own{};
        for (std::size_t i = 0; i < v.size(); ++i) own[i] = v[i].inner;
        inner.pixels(std::span<const typename Inner::Varying>(own.data(), v.size()), out);
    }
    void pixels(std::span<const Varying> v, std::span<const Varying> per_x, std::span<const Varying> per_y,
                std::span<Rgb> out) const noexcept requires(LaneShader<Inner>&& NeedsFootprint<Inner>) {
        std::array<typename Inner::Varying, kLanes> own{}, own_x{}, own_y{};
        for (std::size_t i = 0; i < v.size(); ++i)
            own[i] = v[i].inner, own_x[i] = per_x[i].inner, own_y[i] = per_y[i].inner;
        using Span = std::span<const typename Inner::Varying>;
        inner.pixels(Span(own.data(), v.size()), Span(own_x.data(), v.size()), Span(own_y.data(), v.size()), out);
    }
};

// A Varying's own part (the wrapped shader's under a VertexAlphaShader) and its vertex alpha (1 without).
template <typename Varying>
[[nodiscard]] const auto& own_varying(const Varying& v) noexcept {
    if constexpr (requires { v.inner; }) {
        return v.inner;
    } else {
        return v;
    }
}
template <typename Varying>
[[nodiscard]] float vertex_alpha_of(const Varying& v) noexcept {
    if constexpr (requires { v.inner; }) {
        return v.alpha;
    } else {
        return 1.0F;
    }
}

}  // namespace raster::detail
