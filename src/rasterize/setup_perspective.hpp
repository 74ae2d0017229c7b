#pragma once

#include "camera/clip_triangle.hpp"
#include "rasterize/facet_corners.hpp"
#include "rasterize/triangle_loop.hpp"

#include <raster/camera/perspective_camera.hpp>

#include <vector>

// The perspective front end of the one rasterizer: project to clip space, clip, divide, snap,
// cull, then fill with attributes interpolated through 1/w.
namespace raster::detail {

// The front end of a perspective view in two steps, each of which may be split into ranges run
// on several threads: vertices() takes positions to clip space, snaps those inside every plane
// and makes per-vertex Varyings; facets() then hands `visit(corners)` every triangle of its
// range that faces the camera after clipping, in facet order (a clipped facet as a fan of
// pieces). `band`: how far beyond the image's edges x and y are clipped, in pixels.
template <typename Shader>
class PerspectiveFront {
public:
    using Varying = typename Shader::Varying;
    // For a mesh that passed check_drawable; throws std::invalid_argument for a camera whose
    // size is not the framebuffer's.
    PerspectiveFront(const Framebuffer& colour, const PerspectiveCamera& camera, const Mesh& mesh, const Shader& shader,
                     double band)
        : camera_(camera), mesh_(mesh), shader_(shader), frustum_(colour.width(), colour.height(), band),
          clip_(mesh.positions.size()), snapped_(mesh.positions.size()) {
        if (camera.width() != colour.width() || camera.height() != colour.height()) {
            throw std::invalid_argument("camera and framebuffer differ in size");
        }
        if (!Shader::kFacetNormal && mesh.surface != Surface::faceted) varyings_.resize(mesh.positions.size());
    }

    void vertices(std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            clip_[i] = camera_.clip_from_world(mesh_.positions[i]);
            snapped_[i] =
                frustum_.inside_all(clip_[i]) ? snap_to_subpixel(camera_.screen_from_clip(clip_[i])) : std::nullopt;
            if (!varyings_.empty()) varyings_[i] = vertex_varying(shader_, mesh_, i);
        }
    }

    // Returns the facets with any piece visited.
    template <typename Visit>
    std::size_t facets(std::size_t begin, std::size_t end, Visit visit) const {
        std::size_t drawn = 0;
        for (std::size_t f = begin; f < end; ++f) {
            const Facet& facet = mesh_.facets[f];
            const std::array<glm::dvec4, 3> at{clip_[facet.corners[0]], clip_[facet.corners[1]],
                                               clip_[facet.corners[2]]};
            if (snapped_[facet.corners[0]] && snapped_[facet.corners[1]] && snapped_[facet.corners[2]]) {
                // Most facets need no clipping: cull them before any shading work.
                std::array<ShadedCorner<Varying>, 3> corners{};
                for (std::size_t k = 0; k < 3; ++k)
                    corners[k].at = *snapped_[facet.corners[k]], corners[k].depth = static_cast<float>(at[k].w);
                drawn += visit_if_facing(corners, shader_, mesh_, facet, varyings_, visit) ? 1 : 0;
                continue;
            }
            drawn += clipped(facet, at, visit) ? 1 : 0;
        }
        return drawn;
    }

private:
    // A facet reaching outside some plane, cut to the frustum; whether any piece was visited.
    template <typename Visit>
    bool clipped(const Facet& facet, const std::array<glm::dvec4, 3>& at, Visit& visit) const {
        const std::array<Varying, 3> values = facet_varyings(shader_, mesh_, facet, varyings_);
        const ClippedPolygon<Varying> polygon =
            clip_triangle(frustum_, ClipVertex<Varying>{at[0], values[0]}, ClipVertex<Varying>{at[1], values[1]},
                          ClipVertex<Varying>{at[2], values[2]});
        std::array<ShadedCorner<Varying>, kMaxClippedCorners> corners{};
        bool usable = polygon.size >= 3;
        for (std::size_t k = 0; k < polygon.size && usable; ++k) {
            const ClipVertex<Varying>& vertex = polygon.corners[k];
            const std::optional<SubpixelPoint> point = snap_to_subpixel(camera_.screen_from_clip(vertex.clip));
            usable = point.has_value();  // inside the guard band, so only NaN fails here
            if (usable) corners[k] = {*point, static_cast<float>(vertex.clip.w), vertex.varying};
        }
        if (!usable) return false;
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
        return any;
    }

    const PerspectiveCamera& camera_;
    const Mesh& mesh_;
    const Shader& shader_;
    ClipPlanes frustum_;
    std::vector<glm::dvec4> clip_;
    std::vector<std::optional<SubpixelPoint>> snapped_;  // inside every plane and on screen; else nothing
    std::vector<Varying> varyings_;                      // empty when the shader lights per facet
};

// Both steps on this thread, over the whole mesh.
template <typename Shader, typename Visit>
std::size_t facing_triangles_in_perspective(const Framebuffer& colour, const DepthBuffer* depth_buffer,
                                            const PerspectiveCamera& camera, const Mesh& mesh, const Shader& shader,
                                            double band, Visit visit) {
    check_drawable(colour, depth_buffer, mesh);
    PerspectiveFront<Shader> front(colour, camera, mesh, shader, band);
    front.vertices(0, mesh.positions.size());
    return front.facets(0, mesh.facets.size(), visit);
}

// Draws every triangle facing a perspective camera, into `rows` only when given.
template <typename Shader, Interpolation kMode = Interpolation::perspective>
std::size_t draw_facets_in_perspective(Framebuffer& colour, DepthBuffer* depth_buffer, const PerspectiveCamera& camera,
                                       const Mesh& mesh, const Shader& shader, double band = kGuardBandPixels,
                                       std::optional<PixelRect> rows = std::nullopt) {
    const PixelRect target = rows.value_or(PixelRect{0, 0, colour.width(), colour.height()});
    LaneBatch<Shader> lanes(shader);
    const std::size_t drawn =
        facing_triangles_in_perspective(colour, depth_buffer, camera, mesh, shader, band, [&](const auto& corners) {
            if (misses_rows({corners[0].at, corners[1].at, corners[2].at}, target)) return;  // another band's
            shade_triangle<Shader, FloatDepth, kMode>(colour, depth_buffer, corners, shader, {}, target, &lanes);
        });
    lanes.flush();
    return drawn;
}

}  // namespace raster::detail
