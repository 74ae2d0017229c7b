#pragma once

#include <raster/image/lanes.hpp>

#include "rasterize/lane_batch.hpp"

#include <array>
#include <type_traits>
#include <experimental/simd>

// A few neighbouring pixels of a row of a perspective triangle, their depths and
// interpolation weights computed in SIMD lanes of doubles: the same operations, in the same
// order, as for one pixel, so each lane equals the one-pixel result bit for bit.
namespace raster::detail {

// The barycentric weight of one corner as a plane over pixel coordinates (i, j), measured from
// corner 0 so that small triangles far from the origin keep their precision.
struct WeightPlane {
    double x0, y0;  // corner 0, subpixels
    double per_subpixel_x, per_subpixel_y;
    [[nodiscard]] double at(double i, double j) const noexcept {
        return (i * kSubpixelOne - x0) * per_subpixel_x + (j * kSubpixelOne - y0) * per_subpixel_y;
    }
    [[nodiscard]] double per_pixel_x() const noexcept { return per_subpixel_x * kSubpixelOne; }
    [[nodiscard]] double per_pixel_y() const noexcept { return per_subpixel_y * kSubpixelOne; }
};

// The derivative of a perspective triangle's weight sum 1/w and of its corner terms q1 = a / w1,
// q2 = b / w2 along one screen step that moves the screen weights a, b by da, db: constant
// across the triangle, so found once.
struct PerspectiveStep {
    double dq1, dq2, dsum;
    static PerspectiveStep of(double da, double db, double inv0, double inv1, double inv2) noexcept {
        return {da * inv1, db * inv2, (-da - db) * inv0 + da * inv1 + db * inv2};
    }
};

// How a triangle's attributes vary in perspective: its weight planes, the reciprocal view
// depths of the three corners and the steps of one pixel in x and in y.
struct PerspectiveWeights {
    const WeightPlane& w1;
    const WeightPlane& w2;
    double inv0, inv1, inv2;
    PerspectiveStep per_x, per_y;
    PerspectiveWeights(const WeightPlane& plane1, const WeightPlane& plane2, double inv0_, double inv1_,
                       double inv2_) noexcept
        : w1(plane1), w2(plane2), inv0(inv0_), inv1(inv1_), inv2(inv2_),
          per_x(PerspectiveStep::of(plane1.per_pixel_x(), plane2.per_pixel_x(), inv0_, inv1_, inv2_)),
          per_y(PerspectiveStep::of(plane1.per_pixel_y(), plane2.per_pixel_y(), inv0_, inv1_, inv2_)) {}
};

// The Varying at a point of a perspective triangle whose corner weights through 1/w are q1 / sum
// and q2 / sum (sum = 1 / w, the view depth w) and, for a shader that filters, its change along
// a screen step in x and in y.
template <typename Shader, typename Varying = typename Shader::Varying>
PixelVarying<Varying> perspective_varying(const Varying& base, const Varying& along1, const Varying& along2,
                                          const PerspectiveWeights& p, double q1, double q2, double sum, double w) {
    const double t1 = q1 * w, t2 = q2 * w;
    PixelVarying<Varying> at{base + along1 * static_cast<float>(t1) + along2 * static_cast<float>(t2)};
    if constexpr (NeedsFootprint<Shader>) {
        // The derivative of (q_k / sum) along the step: (dq_k - t_k dsum) / sum.
        const auto change = [&](const PerspectiveStep& d) {
            return along1 * static_cast<float>((d.dq1 - t1 * d.dsum) / sum) +
                   along2 * static_cast<float>((d.dq2 - t2 * d.dsum) / sum);
        };
        at.per_x = change(p.per_x);
        at.per_y = change(p.per_y);
    }
    return at;
}

// What perspective_varying and the depth test need of up to kSize pixels (x + k, y): the view
// depth as stored, and the weights of corners 1 and 2 with, when asked, their steps.
struct PerspectiveRun {
    static constexpr int kSize = 4;  // two SSE2 registers of doubles: spans are often short
    using Floats = std::array<float, kSize>;
    Floats depth{};
    Floats t1{}, t2{};
    Floats x1{}, x2{}, y1{}, y2{};  // d t_k / dx and d t_k / dy

    enum class Need { weights, footprint };
    enum class Precision { double_, single };

    template <Need kNeed, Precision kPrecision = Precision::double_>
    [[gnu::flatten]] void compute(const PerspectiveWeights& p, int x, int y) noexcept {
        namespace stdx = std::experimental;
        using Real = std::conditional_t<kPrecision == Precision::single, float, double>;
        using Reals = stdx::fixed_size_simd<Real, kSize>;
        using FloatLanes = stdx::fixed_size_simd<float, kSize>;
        const auto store = [](const Reals& v, Floats& to) {
            stdx::static_simd_cast<FloatLanes>(v).copy_to(to.data(), stdx::element_aligned);
        };
        const auto real = [](double v) { return static_cast<Real>(v); };
        const Reals i([x](auto k) { return static_cast<Real>(x + static_cast<int>(k)); });
        const auto j = static_cast<Real>(y);
        const auto one = static_cast<Real>(kSubpixelOne);
        const Reals a = (i * one - real(p.w1.x0)) * real(p.w1.per_subpixel_x) +
                        (j * one - real(p.w1.y0)) * real(p.w1.per_subpixel_y);
        const Reals b = (i * one - real(p.w2.x0)) * real(p.w2.per_subpixel_x) +
                        (j * one - real(p.w2.y0)) * real(p.w2.per_subpixel_y);
        const Reals q1 = a * real(p.inv1), q2 = b * real(p.inv2), sum = (Real(1) - a - b) * real(p.inv0) + q1 + q2;
        const Reals w = Real(1) / sum;  // the view depth; one division serves all three
        store(w, depth);
        const Reals u1 = q1 * w, u2 = q2 * w;
        store(u1, t1), store(u2, t2);
        if constexpr (kNeed != Need::footprint) return;
        store((real(p.per_x.dq1) - u1 * real(p.per_x.dsum)) / sum, x1),
            store((real(p.per_x.dq2) - u2 * real(p.per_x.dsum)) / sum, x2);
        store((real(p.per_y.dq1) - u1 * real(p.per_y.dsum)) / sum, y1),
            store((real(p.per_y.dq2) - u2 * real(p.per_y.dsum)) / sum, y2);
    }

    // The Varying of lane k, as perspective_varying gives it.
    template <typename Shader, typename Varying = typename Shader::Varying>
    [[nodiscard]] PixelVarying<Varying> varying(std::size_t k, const Varying& base, const Varying& along1,
                                                const Varying& along2) const {
        PixelVarying<Varying> at{base + along1 * t1[k] + along2 * t2[k]};
        if constexpr (NeedsFootprint<Shader>) {
            at.per_x = along1 * x1[k] + along2 * x2[k];
            at.per_y = along1 * y1[k] + along2 * y2[k];
        }
        return at;
    }
};

}  // namespace raster::detail
