#include <raster/image/subpixel.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace raster {

std::optional<SubpixelPoint> snap_to_subpixel(glm::dvec2 screen) noexcept {
    constexpr double limit = double{kMaxSubpixelCoordinate} * kSubpixelOne;
    const double x = screen.x * kSubpixelOne + 0.5;
    const double y = screen.y * kSubpixelOne + 0.5;
    // Beyond limit + 1 the floor is beyond the limit too; written so that NaN fails the test.
    if (!(std::abs(x) < limit + 1.0 && std::abs(y) < limit + 1.0)) return std::nullopt;
    // floor by truncation, exact in this range: std::floor is a library call without SSE4.1.
    const auto floor_of = [](double v) {
        const auto t = static_cast<std::int64_t>(v);
        return static_cast<double>(t) > v ? t - 1 : t;
    };
    const std::int64_t fx = floor_of(x), fy = floor_of(y);
    if (!(std::abs(fx) <= static_cast<std::int64_t>(limit) && std::abs(fy) <= static_cast<std::int64_t>(limit)))
        return std::nullopt;
    return SubpixelPoint{static_cast<std::int32_t>(fx), static_cast<std::int32_t>(fy)};
}

}  // namespace raster
