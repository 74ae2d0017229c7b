#include <raster/geometry/mesh.hpp>
#include <raster/shade/normal_map.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace raster {

namespace {

// `mapped` turned by the tangent made perpendicular to n again at this pixel; zero where it has no
// direction apart from n.
glm::vec3 tangent_mapped(glm::vec3 n, glm::vec3 mapped, glm::vec4 tangent) noexcept {
    const glm::vec3 along(tangent);
    const glm::vec3 t = unit_or_zero(along - n * glm::dot(n, along));
    if (!(glm::dot(t, t) > 0.0F)) return glm::vec3(0.0F);
    const glm::vec3 b = glm::cross(n, t) * (tangent.w < 0.0F ? -1.0F : 1.0F);
    return unit_or_zero(t * mapped.x + b * mapped.y + n * mapped.z);
}

}  // namespace

glm::vec3 normal_mapped(glm::vec3 n, LinearRgb texel, float scale, glm::vec4 tangent, glm::vec3 position_per_x,
                        glm::vec3 position_per_y, const UvFootprint& footprint) noexcept {
    const glm::vec3 mapped((texel.r * 2.0F - 1.0F) * scale, (texel.g * 2.0F - 1.0F) * scale, texel.b * 2.0F - 1.0F);
    // A texel that is no direction (the zero vector, 128 128 128) leaves the surface's normal.
    if (!(glm::dot(mapped, mapped) > 1e-4F)) return n;
    const glm::vec3 by_tangent = tangent_mapped(n, mapped, tangent);
    if (glm::dot(by_tangent, by_tangent) > 0.0F) return by_tangent;
    const glm::vec3 dp1 = position_per_x, dp2 = position_per_y;
    const glm::vec2 duv1 = footprint.per_pixel_x, duv2 = footprint.per_pixel_y;
    const glm::vec3 dp2perp = glm::cross(dp2, n), dp1perp = glm::cross(n, dp1);
    const glm::vec3 t = dp2perp * duv1.x + dp1perp * duv2.x;
    const glm::vec3 b = dp2perp * duv1.y + dp1perp * duv2.y;
    const float longest = std::max(glm::dot(t, t), glm::dot(b, b));
    if (!(longest > 0.0F) || !std::isfinite(longest)) return n;
    const float inverse = 1.0F / std::sqrt(longest);
    const glm::vec3 turned = unit_or_zero(t * (mapped.x * inverse) + b * (mapped.y * inverse) + n * mapped.z);
    return glm::dot(turned, turned) > 0.0F ? turned : n;
}

}  // namespace raster
