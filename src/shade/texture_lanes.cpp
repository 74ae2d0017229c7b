#include <raster/shade/texture.hpp>

#include "shade/simd_lanes.hpp"
#include "shade/texture_wrap.hpp"

#include <cmath>

// Texture::sample in lanes: the coordinates, weights and blends in SIMD registers with the
// scalar code's operations in its order, the texel reads (a gather) lane by lane.
namespace raster {

namespace {

using lanes::Floats;
using lanes::Mask;
namespace stdx = lanes::stdx;

// detail::wrapped per lane.
Floats wrapped_lanes(const Floats& c, TextureWrap wrap) noexcept {
    Floats out;
    if (wrap == TextureWrap::clamp) {
        out = c;  // std::clamp(c, 0, 1): 0 below, 1 above
        stdx::where(c < 0.0F, out) = 0.0F;
        stdx::where(Floats(1.0F) < c, out) = 1.0F;
    } else {
        out = c - stdx::floor(c);
        stdx::where(!(out < 1.0F), out) = 0.0F;
    }
    stdx::where(!stdx::isfinite(c), out) = 0.0F;
    return out;
}

}  // namespace

void Texture::bilinear_lanes(const std::array<std::size_t, kLanes>& levels, const LaneFloats& u, const LaneFloats& v,
                             TextureWrap wrap, LaneRgb& out, int count) const noexcept {
    LaneFloats widths{}, heights{};
    for (std::size_t i = 0; i < kLanes; ++i) {
        widths[i] = static_cast<float>(levels_[levels[i]].width());
        heights[i] = static_cast<float>(levels_[levels[i]].height());
    }
    // Texel centres sit at half-integers, so the four around the point start half a texel back.
    const Floats x = wrapped_lanes(lanes::load(u), wrap) * lanes::load(widths) - 0.5F;
    const Floats y = (1.0F - wrapped_lanes(lanes::load(v), wrap)) * lanes::load(heights) - 0.5F;
    const Floats x_floor = stdx::floor(x), y_floor = stdx::floor(y);
    const Floats fx = x - x_floor, fy = y - y_floor;
    LaneRgb corner[4];  // (x0, y0), (x1, y0), (x0, y1), (x1, y1)
    for (int i = 0; i < count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const Framebuffer& level = levels_[levels[k]];
        const int w = level.width(), h = level.height();
        const auto x0 = static_cast<int>(x_floor[k]), y0 = static_cast<int>(y_floor[k]);
        const int xa = detail::wrapped_index(x0, w, wrap), xb = detail::wrapped_index(x0 + 1, w, wrap);
        const int ya = detail::wrapped_index(y0, h, wrap), yb = detail::wrapped_index(y0 + 1, h, wrap);
        put_lane(corner[0], k, texel(level, xa, ya)), put_lane(corner[1], k, texel(level, xb, ya));
        put_lane(corner[2], k, texel(level, xa, yb)), put_lane(corner[3], k, texel(level, xb, yb));
    }
    const Floats gx = 1.0F - fx, gy = 1.0F - fy;
    const auto blend = [&](const LaneFloats LaneRgb::*channel, LaneFloats& to) {
        const Floats top = lanes::load(corner[0].*channel) * gx + lanes::load(corner[1].*channel) * fx;
        const Floats bottom = lanes::load(corner[2].*channel) * gx + lanes::load(corner[3].*channel) * fx;
        lanes::store(top * gy + bottom * fy, to);
    };
    blend(&LaneRgb::r, out.r), blend(&LaneRgb::g, out.g), blend(&LaneRgb::b, out.b);
}

[[gnu::flatten]] void Texture::sample_lanes(const LaneUvs& at, Sampler sampler, LaneRgb& out,
                                            int count) const noexcept {
    if (sampler.filter == TextureFilter::nearest) {
        for (int i = 0; i < count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            put_lane(out, k, nearest(levels_.front(), {at.u[k], at.v[k]}, sampler.wrap));
        }
        return;
    }
    std::array<std::size_t, kLanes> first{}, second{};
    Mask two(false);
    Floats blend(0.0F);
    if (sampler.filter == TextureFilter::trilinear && levels_.size() > 1) {
        // OpenGL's level of detail: log2 of the longer of the pixel's two steps, measured in texels.
        const auto across = static_cast<float>(width()), down = static_cast<float>(height());
        const Floats ax = lanes::load(at.u_per_x) * across, ay = lanes::load(at.v_per_x) * down;
        const Floats bx = lanes::load(at.u_per_y) * across, by = lanes::load(at.v_per_y) * down;
        const Floats along_x = stdx::sqrt(ax * ax + ay * ay), along_y = stdx::sqrt(bx * bx + by * by);
        Floats rho = along_x;  // std::max(along_x, along_y)
        stdx::where(along_x < along_y, rho) = along_y;
        const auto last = static_cast<float>(levels_.size() - 1);
        for (int i = 0; i < count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            const float lod = std::log2(rho[k]);
            if (!(lod > 0.0F)) continue;  // magnified, or no footprint at all (NaN): level 0
            if (lod >= last) {
                first[k] = levels_.size() - 1;
                continue;
            }
            const float lower = std::floor(lod);
            first[k] = static_cast<std::size_t>(lower), second[k] = first[k] + 1;
            blend[k] = lod - lower;
            two[k] = true;
        }
    }
    bilinear_lanes(first, at.u, at.v, sampler.wrap, out, count);
    if (stdx::none_of(two)) return;
    for (std::size_t k = 0; k < kLanes; ++k) second[k] = two[k] ? second[k] : first[k];
    LaneRgb next;
    bilinear_lanes(second, at.u, at.v, sampler.wrap, next, count);
    const Floats keep = 1.0F - blend;
    const auto mix = [&](LaneFloats& channel, const LaneFloats& other) {
        Floats mixed = lanes::load(channel);
        stdx::where(two, mixed) = lanes::load(channel) * keep + lanes::load(other) * blend;
        lanes::store(mixed, channel);
    };
    mix(out.r, next.r), mix(out.g, next.g), mix(out.b, next.b);
}

}  // namespace raster
