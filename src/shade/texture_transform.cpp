#include <raster/shade/texture_transform.hpp>

#include <cmath>
#include <cstddef>

namespace raster {

MovedUv moved_uv(const TextureTransform& transform, glm::vec2 uv, const UvFootprint& footprint) noexcept {
    if (transform.identity()) return {uv, footprint};
    const float c = std::cos(transform.rotation), s = std::sin(transform.rotation);
    const glm::vec2 k = transform.scale;
    // The specification's T * R * S in glTF's frame, where v' = 1 - v: a point is turned over,
    // moved and turned back; a step per pixel only has its v turned over.
    const auto linear = [&](glm::vec2 d) {
        return glm::vec2(c * k.x * d.x + s * k.y * d.y, -s * k.x * d.x + c * k.y * d.y);
    };
    const glm::vec2 gltf = linear({uv.x, 1.0F - uv.y}) + transform.offset;
    const auto step = [&](glm::vec2 d) {
        const glm::vec2 turned = linear({d.x, -d.y});
        return glm::vec2(turned.x, -turned.y);
    };
    return {{gltf.x, 1.0F - gltf.y}, {step(footprint.per_pixel_x), step(footprint.per_pixel_y)}};
}

LaneUvs moved_lanes(const TextureTransform& transform, const LaneUvs& uvs, int count) noexcept {
    LaneUvs out = uvs;
    for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
        const MovedUv m = moved_uv(transform, {uvs.u[i], uvs.v[i]},
                                   {{uvs.u_per_x[i], uvs.v_per_x[i]}, {uvs.u_per_y[i], uvs.v_per_y[i]}});
        out.u[i] = m.uv.x, out.v[i] = m.uv.y;
        out.u_per_x[i] = m.footprint.per_pixel_x.x, out.v_per_x[i] = m.footprint.per_pixel_x.y;
        out.u_per_y[i] = m.footprint.per_pixel_y.x, out.v_per_y[i] = m.footprint.per_pixel_y.y;
    }
    return out;
}

}  // namespace raster
