#pragma once

#include <raster/camera/ortho_camera.hpp>
#include <raster/geometry/mesh.hpp>

#include "rasterize/facet_corners.hpp"
#include "rasterize/triangle_loop.hpp"

#include <cmath>
#include <optional>
#include <vector>

// The orthographic front end: project, snap, cull, then fill with attributes linear on screen.
namespace raster::detail {

struct ScreenVertex {
    std::optional<SubpixelPoint> at;  // nothing when not finite or too far away
    float depth = 0.0F;
};

// The front end of an orthographic view in two steps, each of which may be split into ranges
// run on several threads: vertices() projects positions and makes per-vertex Varyings;
// facets() then hands `visit(corners)` every facet of its range facing the camera, in order.
template <typename Shader>
class OrthoFront {
public:
    using Varying = typename Shader::Varying;
    // For a mesh that passed check_drawable: its facets name only vertices it has.
    OrthoFront(const OrthoCamera& camera, const Mesh& mesh, const Shader& shader)
        : camera_(camera), mesh_(mesh), shader_(shader), screen_(mesh.positions.size()) {
        if (!Shader::kFacetNormal && mesh.surface != Surface::faceted) varyings_.resize(mesh.positions.size());
    }

    void vertices(std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const glm::dvec3 view = camera_.view_from_world(mesh_.positions[i]);
            // A depth beyond the limit is treated like a position too far away: the facet is skipped.
            const bool usable_depth = std::abs(view.z) <= kMaxViewDepth;
            screen_[i] = {usable_depth ? snap_to_subpixel(camera_.screen_from_view(view)) : std::nullopt,
                          static_cast<float>(view.z)};
            if (!varyings_.empty()) varyings_[i] = vertex_varying(shader_, mesh_, i);
        }
    }

    // Returns the facets visited.
    template <typename Visit>
    std::size_t facets(std::size_t begin, std::size_t end, Visit visit) const {
        std::size_t drawn = 0;
        for (std::size_t f = begin; f < end; ++f) {
            const Facet& facet = mesh_.facets[f];
            std::array<ShadedCorner<Varying>, 3> corners{};
            bool on_screen = true;
            for (std::size_t k = 0; k < 3 && on_screen; ++k) {
                const ScreenVertex& vertex = screen_[facet.corners[k]];
                on_screen = vertex.at.has_value();
                if (on_screen) corners[k].at = *vertex.at, corners[k].depth = vertex.depth;
            }
            if (!on_screen) continue;
            drawn += visit_if_facing(corners, shader_, mesh_, facet, varyings_, visit) ? 1 : 0;
        }
        return drawn;
    }

private:
    const OrthoCamera& camera_;
    const Mesh& mesh_;
    const Shader& shader_;
    std::vector<ScreenVertex> screen_;
    std::vector<Varying> varyings_;  // empty when the shader lights per facet
};

// Both steps on this thread, over the whole mesh.
template <typename Shader, typename Visit>
std::size_t facing_triangles(const Framebuffer& colour, const DepthBuffer* depth_buffer, const OrthoCamera& camera,
                             const Mesh& mesh, const Shader& shader, Visit visit) {
    check_drawable(colour, depth_buffer, mesh);
    OrthoFront<Shader> front(camera, mesh, shader);
    front.vertices(0, mesh.positions.size());
    return front.facets(0, mesh.facets.size(), visit);
}

// Draws every facet facing an orthographic camera, into `rows` only when given.
template <typename Shader, typename DepthFormat = FloatDepth>
std::size_t draw_facets(Framebuffer& colour, DepthBuffer* depth_buffer, const OrthoCamera& camera, const Mesh& mesh,
                        const Shader& shader, DepthFormat stored = {}, std::optional<PixelRect> rows = std::nullopt) {
    const PixelRect target = rows.value_or(PixelRect{0, 0, colour.width(), colour.height()});
    LaneBatch<Shader> lanes(shader);
    const std::size_t drawn = facing_triangles(colour, depth_buffer, camera, mesh, shader, [&](const auto& corners) {
        if (misses_rows({corners[0].at, corners[1].at, corners[2].at}, target)) return;  // another band's
        shade_triangle(colour, depth_buffer, corners, shader, stored, target, &lanes);
    });
    lanes.flush();
    return drawn;
}

}  // namespace raster::detail
