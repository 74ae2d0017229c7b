#include <raster/subpixel.hpp>

#include <cmath>

namespace raster {

std::optional<SubpixelPoint> snap_to_subpixel(glm::dvec2 screen) noexcept {
    constexpr double limit = double{kMaxSubpixelCoordinate} * kSubpixelOne;
    const double x = std::floor(screen.x * kSubpixelOne + 0.5);
    const double y = std::floor(screen.y * kSubpixelOne + 0.5);
    // Written so that NaN fails the test too.
    if (!(std::abs(x) <= limit && std::abs(y) <= limit)) return std::nullopt;
    return SubpixelPoint{static_cast<std::int32_t>(x), static_cast<std::int32_t>(y)};
}

}  // namespace raster
