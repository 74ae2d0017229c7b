#pragma once

#include "clip_triangle.hpp"
#include "shaded_triangle.hpp"

#include <raster/perspective_camera.hpp>

#include <vector>

// The perspective front end of the one rasterizer: project to clip space, clip, divide, snap,
// cull, then fill with attributes interpolated through 1/w.
namespace raster::detail {

// `visit(corners)` gets every triangle that faces the camera after clipping, in facet order
// (a clipped facet as a fan of pieces); `band`: how far beyond the image's edges x and y are
// clipped, in pixels (the lab compares). Returns the facets with any piece visited.
template <typename Shader, typename Visit>
std::size_t facing_triangles_in_perspective(const Framebuffer& colour, const DepthBuffer* depth_buffer,
                                            const PerspectiveCamera& camera, const Mesh& mesh, const Shader& shader,
                                            double band, Visit visit) {
    using Varying = typename Shader::Varying;
    check_drawable(colour, depth_buffer, mesh);
    if (camera.width() != colour.width() || camera.height() != colour.height()) {
        throw std::invalid_argument("camera and framebuffer differ in size");
    }
    const ClipPlanes frustum(colour.width(), colour.height(), band);
    std::vector<glm::dvec4> clip;
    std::vector<std::optional<SubpixelPoint>> snapped;  // a vertex inside every plane, on screen; else nothing
    clip.reserve(mesh.positions.size());
    snapped.reserve(mesh.positions.size());
    for (const glm::vec3& position : mesh.positions) {
        clip.push_back(camera.clip_from_world(position));
        snapped.push_back(frustum.inside_all(clip.back()) ? snap_to_subpixel(camera.screen_from_clip(clip.back())) : std::nullopt);
    }
    const std::vector<Varying> varyings = vertex_varyings(shader, mesh);
    std::size_t drawn = 0;
    for (const Facet& facet : mesh.facets) {
        const std::array<glm::dvec4, 3> at{clip[facet.corners[0]], clip[facet.corners[1]], clip[facet.corners[2]]};
        if (snapped[facet.corners[0]] && snapped[facet.corners[1]] && snapped[facet.corners[2]]) {
            // Most facets need no clipping: cull them before any shading work.
            std::array<ShadedCorner<Varying>, 3> corners{};
            for (std::size_t k = 0; k < 3; ++k) corners[k].at = *snapped[facet.corners[k]], corners[k].depth = static_cast<float>(at[k].w);
            const std::array<SubpixelPoint, 3> points{corners[0].at, corners[1].at, corners[2].at};
            if (twice_signed_area(points) <= 0) continue;  // facing away or edge-on
            ++drawn;
            const std::array<Varying, 3> values = facet_varyings(shader, mesh, facet, varyings);
            for (std::size_t k = 0; k < 3; ++k) corners[k].varying = values[k];
            visit(corners);
            continue;
        }
        const std::array<Varying, 3> values = facet_varyings(shader, mesh, facet, varyings);
        const ClippedPolygon<Varying> polygon = clip_triangle(frustum, ClipVertex<Varying>{at[0], values[0]},
                                                              ClipVertex<Varying>{at[1], values[1]},
                                                              ClipVertex<Varying>{at[2], values[2]});
        std::array<ShadedCorner<Varying>, kMaxClippedCorners> corners{};
        bool usable = polygon.size >= 3;
        for (std::size_t k = 0; k < polygon.size && usable; ++k) {
            const ClipVertex<Varying>& vertex = polygon.corners[k];
            const std::optional<SubpixelPoint> point = snap_to_subpixel(camera.screen_from_clip(vertex.clip));
            usable = point.has_value();  // inside the guard band, so only NaN fails here
            if (usable) corners[k] = {*point, static_cast<float>(vertex.clip.w), vertex.varying};
        }
        if (!usable) continue;
        // A fan over the clipped polygon; every piece keeps the facet's winding, so each is culled
        // on its own snapped area like an unclipped facet.
        bool any = false;
        for (std::size_t k = 1; k + 1 < polygon.size; ++k) {
            const std::array<ShadedCorner<Varying>, 3> piece{corners[0], corners[k], corners[k + 1]};
            const std::array<SubpixelPoint, 3> points{piece[0].at, piece[1].at, piece[2].at};
            if (twice_signed_area(points) <= 0) continue;  // facing away or edge-on
            any = true;
            visit(piece);
        }
        drawn += any ? 1 : 0;
    }
    return drawn;
}

// Draws every triangle facing a perspective camera, into `rows` only when given.
template <typename Shader, Interpolation kMode = Interpolation::perspective>
std::size_t draw_facets_in_perspective(Framebuffer& colour, DepthBuffer* depth_buffer, const PerspectiveCamera& camera,
                                       const Mesh& mesh, const Shader& shader, double band = kGuardBandPixels,
                                       std::optional<PixelRect> rows = std::nullopt) {
    const PixelRect target = rows.value_or(PixelRect{0, 0, colour.width(), colour.height()});
    return facing_triangles_in_perspective(colour, depth_buffer, camera, mesh, shader, band, [&](const auto& corners) {
        if (misses_rows({corners[0].at, corners[1].at, corners[2].at}, target)) return;  // another band's
        shade_triangle<Shader, FloatDepth, kMode>(colour, depth_buffer, corners, shader, {}, target);
    });
}

}  // namespace raster::detail
