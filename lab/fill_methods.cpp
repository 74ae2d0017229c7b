#include "fill_methods.hpp"

#include "fill_kernels.hpp"

#include <raster/image/subpixel.hpp>
#include <raster/rasterize/fill.hpp>

#include <array>

namespace lab {

// The product: exact 64-bit edge functions on 8-bit corners, solved for each row's span.
void kernels::span_exact(std::span<const glm::dvec2> corners, Coverage& target) {
    std::array<raster::SubpixelPoint, kernels::kMaxCorners> snapped{};
    if (corners.size() > kernels::kMaxCorners) return;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const auto point = raster::snap_to_subpixel(corners[i]);
        if (!point) return;
        snapped[i] = *point;
    }
    raster::rasterize_convex(std::span(snapped.data(), corners.size()), target.rect(),
                             [&target](raster::Span span) { target.hit_row(span.y, span.x_begin, span.x_end); });
}

namespace {

constexpr std::array<FillMethod, 7> kFillMethods{{
    {"seed-bbox-float", "seed: bbox + float on whole pixels", kernels::seed_bbox_float, false},
    {"edge-float", "float edge functions (8-bit)", kernels::edge_float, false},
    {"edge-fixed4", "integer edge functions (4-bit)", kernels::edge_fixed4, false},
    {"edge-fixed8", "integer edge functions (8-bit)", kernels::edge_fixed8, false},
    {"blocked-fixed8", "8x8 blocks (8-bit)", kernels::blocked_fixed8, false},
    {"scanline-float", "double scanline (8-bit)", kernels::scanline_float, false},
    {"span-exact8", "exact spans (8-bit): product", kernels::span_exact, true},
}};

}  // namespace

std::span<const FillMethod> fill_methods() { return kFillMethods; }

const FillMethod& product_fill() { return kFillMethods.back(); }

}  // namespace lab
