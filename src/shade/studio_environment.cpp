#include <raster/shade/surroundings.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raster {
namespace {

// A soft round window: full at its centre, fading to nothing `radius` radians out.
float window(glm::vec3 toward, glm::vec3 centre, float radius) noexcept {
    const float angle = std::acos(std::clamp(glm::dot(toward, glm::normalize(centre)), -1.0F, 1.0F));
    const float t = std::clamp(1.0F - angle / radius, 0.0F, 1.0F);
    return t * t * (3.0F - 2.0F * t);  // smoothstep: no hard edge to alias in a mirror
}

}  // namespace

LinearRgb studio_radiance(glm::vec3 toward) noexcept {
    const float length = glm::length(toward);
    if (!(length > 0.0F) || !std::isfinite(length)) return {};
    const glm::vec3 d = toward / length;
    // Ceiling 0.8 to horizon 0.45 above; horizon 0.3 to floor 0.08 below, over a soft band.
    float level = d.y >= 0.0F ? 0.45F + 0.35F * std::sqrt(d.y) : 0.08F + 0.22F * std::exp(-8.0F * -d.y);
    level += 2.5F * window(d, {-0.6F, 0.55F, -0.6F}, 0.45F);  // key window, above and in front-left
    level += 1.2F * window(d, {0.8F, 0.35F, 0.5F}, 0.35F);    // fill window, behind and to the right
    return {level, level, level};
}

}  // namespace raster
