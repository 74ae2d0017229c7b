#pragma once

#include <raster/rasterize/shader.hpp>

// The shader of a depth pass (raster/rasterize/shader.hpp's DepthOnly).
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
static_assert(Shader<DepthOnlyShader> && DepthOnly<DepthOnlyShader>);

}  // namespace raster::detail
