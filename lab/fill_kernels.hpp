#pragma once

#include "coverage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <glm/vec2.hpp>

// The fill methods' bodies, spread over a few files, and what they share. Internal to the lab.
namespace lab::kernels {

inline constexpr std::size_t kMaxCorners = 8;

struct Box {
    std::int64_t x0, y0, x1, y1;  // inclusive pixel bounds, clipped to the target
};

inline std::optional<Box> clipped_box(double min_x, double min_y, double max_x, double max_y, const Coverage& target) {
    const PixelRect& r = target.rect();
    const Box box{
        std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(min_x)), r.x),
        std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(min_y)), r.y),
        std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(max_x)), std::int64_t{r.x} + r.width - 1),
        std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(max_y)), std::int64_t{r.y} + r.height - 1)};
    if (box.x0 > box.x1 || box.y0 > box.y1) return std::nullopt;
    return box;
}

inline bool finite(std::span<const glm::dvec2> corners) {
    return std::all_of(corners.begin(), corners.end(),
                       [](glm::dvec2 c) { return std::isfinite(c.x) && std::isfinite(c.y); });
}

void seed_bbox_float(std::span<const glm::dvec2> corners, Coverage& target);
void edge_float(std::span<const glm::dvec2> corners, Coverage& target);
void edge_fixed4(std::span<const glm::dvec2> corners, Coverage& target);
void edge_fixed8(std::span<const glm::dvec2> corners, Coverage& target);
void blocked_fixed8(std::span<const glm::dvec2> corners, Coverage& target);
void scanline_float(std::span<const glm::dvec2> corners, Coverage& target);
void span_exact(std::span<const glm::dvec2> corners, Coverage& target);

}  // namespace lab::kernels
