#pragma once

#include <raster/rasterize/framebuffer.hpp>
#include <raster/shade/shaders.hpp>

// The shader of a depth pass: it carries nothing and colours nothing, so the rasterizers only
// test and write depth for it (doc/conventions.md#depth).
namespace raster::detail {

struct DepthOnlyShader {
    struct Varying {
        friend Varying operator+(Varying, Varying) noexcept { return {}; }
        friend Varying operator-(Varying, Varying) noexcept { return {}; }
        friend Varying operator*(Varying, float) noexcept { return {}; }
        friend bool operator==(Varying, Varying) noexcept = default;
    };
    static constexpr bool kFacetNormal = true;  // no vertex normals to pose
    static constexpr bool kDepthOnly = true;
    [[nodiscard]] static Varying vertex(const Corner& /*corner*/) noexcept { return {}; }
    [[nodiscard]] static Rgb pixel(Varying /*nothing*/) noexcept { return {}; }
};

// A shader that writes depth and no colour.
template <typename Shader>
concept DepthOnly = requires { requires Shader::kDepthOnly; };

}  // namespace raster::detail
