#pragma once

#include <raster/rasterize/depth_buffer.hpp>
#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/framebuffer.hpp>

#include <raster/geometry/mesh.hpp>
#include <raster/camera/ortho_camera.hpp>
#include <raster/shade/shaders.hpp>

#include "rasterize/depth_only.hpp"
#include "rasterize/lane_batch.hpp"
#include "rasterize/perspective_run.hpp"

#include <algorithm>
#include <array>
#include <concepts>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

// The one rasterizer behind every shader: exact coverage from rasterize_convex, attributes
// interpolated linearly in screen space (exact for an orthographic view).
namespace raster::detail {

// View depths beyond this (world units) are refused, so that depth arithmetic stays finite.
inline constexpr double kMaxViewDepth = 1e18;

// How a view depth is kept: the product stores the float itself; the lab also tries fixed-point
// codes (kept in the same float buffer, exact up to 24 bits).
struct FloatDepth {
    [[nodiscard]] float operator()(float depth) const noexcept { return depth; }
};

template <typename Varying>
struct ShadedCorner {
    SubpixelPoint at;
    float depth;
    Varying varying;
};

// Weights of corners 1 and 2: w1 = ((P - p0) x b) / (a x b), w2 = (a x (P - p0)) / (a x b),
// with a = p1 - p0 and b = p2 - p0; a x b is the exact twice_signed_area, never zero here.
inline std::array<WeightPlane, 2> weight_planes(SubpixelPoint p0, SubpixelPoint p1, SubpixelPoint p2,
                                                std::int64_t twice_area) noexcept {
    const double x0 = p0.x, y0 = p0.y;
    const double ax = p1.x - x0, ay = p1.y - y0, bx = p2.x - x0, by = p2.y - y0;
    const auto cross = static_cast<double>(twice_area);
    return {WeightPlane{x0, y0, by / cross, -bx / cross}, WeightPlane{x0, y0, -ay / cross, ax / cross}};
}

// How attributes vary across the screen: linearly for an orthographic view; through 1/w for a
// perspective one, where each corner's depth is its view depth w > 0. The lab also tries the
// perspective weights in float (perspective_float) against the product's double.
enum class Interpolation { screen_linear, perspective, perspective_float };

// Fills one triangle facing the camera. Varying needs +, - and * float; corner 0 anchors the
// interpolation (v0 + w1 (v1 - v0) + w2 (v2 - v0)), so equal corners give that value exactly.
// `rows`, when given, limits the writes to a band of rows: one strip of a render in strips.
// The pixels go through `batch` when given (the caller flushes it), else through one of its own.
template <typename Shader, typename DepthFormat = FloatDepth, Interpolation kMode = Interpolation::screen_linear>
void shade_triangle(Framebuffer& colour, DepthBuffer* depth,
                    const std::array<ShadedCorner<typename Shader::Varying>, 3>& corners, const Shader& shader,
                    DepthFormat stored = {}, std::optional<PixelRect> rows = std::nullopt, LaneBatch<Shader>* batch = nullptr) {
    using Varying = typename Shader::Varying;
    const std::array<SubpixelPoint, 3> points{corners[0].at, corners[1].at, corners[2].at};
    const std::int64_t twice_area = twice_signed_area(points);
    if (twice_area == 0) return;  // covers nothing, and the weights would divide by zero
    const std::array<WeightPlane, 2> planes = weight_planes(points[0], points[1], points[2], twice_area);
    const WeightPlane& w1 = planes[0];  // not a structured binding: clang 14 cannot capture those
    const WeightPlane& w2 = planes[1];
    const Varying base = corners[0].varying;
    const Varying along1 = corners[1].varying - base;
    const Varying along2 = corners[2].varying - base;
    const Varying step = along1 * static_cast<float>(w1.per_pixel_x()) + along2 * static_cast<float>(w2.per_pixel_x());
    const Varying step_y = along1 * static_cast<float>(w1.per_pixel_y()) + along2 * static_cast<float>(w2.per_pixel_y());
    const double z0 = corners[0].depth;
    const double z1 = corners[1].depth - z0, z2 = corners[2].depth - z0;
    const auto z_step = static_cast<float>(z1 * w1.per_pixel_x() + z2 * w2.per_pixel_x());
    std::uint8_t* const pixels = colour.pixels();
    const std::size_t width = static_cast<std::size_t>(colour.width());
    const PixelRect clip = rows.value_or(PixelRect{0, 0, colour.width(), colour.height()});
    // A Varying equal at all three corners (flat shading) is the same at every pixel: shaded
    // once here, the pixels only take depth and the write. The colour is the one pixel() would give.
    bool constant = false;
    Rgb constant_colour{};
    if constexpr (!NeedsFootprint<Shader> && std::equality_comparable<Varying>) {
        constant = corners[1].varying == base && corners[2].varying == base;
        if (constant) constant_colour = shader.pixel(base);
    }

    LaneBatch<Shader> own(shader);
    LaneBatch<Shader>& lanes = batch != nullptr ? *batch : own;
    if (constant) lanes.flush();  // its pixels are written at once: earlier triangles' queued ones first

    if constexpr (kMode != Interpolation::screen_linear) {
        // Screen weights a, b of corners 1 and 2 become b_k / w_k over their sum: the weights
        // of the surface point seen there; the sum is 1 / w, so the view depth comes with them.
        const double inv0 = 1.0 / corners[0].depth, inv1 = 1.0 / corners[1].depth, inv2 = 1.0 / corners[2].depth;
        const PerspectiveWeights weights(w1, w2, inv0, inv1, inv2);
        constexpr auto kNeed = NeedsFootprint<Shader> ? PerspectiveRun::Need::footprint : PerspectiveRun::Need::weights;
        constexpr auto kPrecision = kMode == Interpolation::perspective_float ? PerspectiveRun::Precision::single : PerspectiveRun::Precision::double_;
        rasterize_convex(points, clip, [&](Span span) {
            std::uint8_t* out = pixels + (static_cast<std::size_t>(span.y) * width + static_cast<std::size_t>(span.x_begin)) * 3;
            float* nearest = depth != nullptr ? depth->row(span.y) + span.x_begin : nullptr;
            if (constant || DepthOnly<Shader>) {
                // Depth and one colour: a pixel at a time is quickest, the spans being short.
                for (int x = span.x_begin; x < span.x_end; ++x, out += 3) {
                    if (nearest != nullptr) {
                        const double a = w1.at(x, span.y), b = w2.at(x, span.y);
                        const float z = stored(static_cast<float>(1.0 / ((1.0 - a - b) * inv0 + a * inv1 + b * inv2)));
                        if (z > nearest[x - span.x_begin]) continue;  // something nearer is already there
                        nearest[x - span.x_begin] = z;
                    }
                    if constexpr (!DepthOnly<Shader>) out[0] = constant_colour.r, out[1] = constant_colour.g, out[2] = constant_colour.b;
                }
                return;
            }
            PerspectiveRun run;
            for (int x = span.x_begin; x < span.x_end; x += PerspectiveRun::kSize) {
                run.compute<kNeed, kPrecision>(weights, x, span.y);
                const auto n = static_cast<std::size_t>(std::min(PerspectiveRun::kSize, span.x_end - x));
                for (std::size_t k = 0; k < n; ++k, out += 3) {
                    if (nearest != nullptr) {
                        const float z = stored(run.depth[k]);
                        float& there = nearest[static_cast<std::size_t>(x - span.x_begin) + k];
                        if (z > there) continue;  // something nearer is already there
                        there = z;
                    }
                    lanes.add(out, 1, run.varying<Shader>(k, base, along1, along2));
                }
            }
        });
        if (batch == nullptr) lanes.flush();
        return;
    }
    rasterize_convex(points, clip, [&](Span span) {
        const double i = span.x_begin, j = span.y;
        const double a = w1.at(i, j), b = w2.at(i, j);
        Varying varying = base + along1 * static_cast<float>(a) + along2 * static_cast<float>(b);
        const auto z_start = static_cast<float>(z0 + z1 * a + z2 * b);
        std::uint8_t* out = pixels + (static_cast<std::size_t>(span.y) * width + static_cast<std::size_t>(span.x_begin)) * 3;
        float* nearest = depth != nullptr ? depth->row(span.y) + span.x_begin : nullptr;
        for (int k = 0; k < span.x_end - span.x_begin; ++k, out += 3, varying = varying + step) {
            if (nearest != nullptr) {
                const float z = stored(z_start + z_step * static_cast<float>(k));
                if (z > nearest[k]) continue;  // something nearer is already there
                nearest[k] = z;
            }
            if constexpr (DepthOnly<Shader>) continue;
            if (constant) {
                out[0] = constant_colour.r, out[1] = constant_colour.g, out[2] = constant_colour.b;
                continue;
            }
            lanes.add(out, 1, {varying, step, step_y});  // the steps are constant across the triangle
        }
    });
    if (batch == nullptr) lanes.flush();
}

// Throws std::invalid_argument for a depth buffer of another size or a mesh whose facets or
// normals do not match its vertices.
inline void check_drawable(const Framebuffer& colour, const DepthBuffer* depth_buffer, const Mesh& mesh) {
    if (depth_buffer != nullptr && (depth_buffer->width() != colour.width() || depth_buffer->height() != colour.height())) {
        throw std::invalid_argument("depth buffer and framebuffer differ in size");
    }
    if (mesh.normals.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.normals.size()) + " normals for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.uvs.size()) + " texture coordinates for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    if (!mesh.colours.empty() && mesh.colours.size() != mesh.positions.size()) {
        throw std::invalid_argument("mesh has " + std::to_string(mesh.colours.size()) + " colours for " +
                                    std::to_string(mesh.positions.size()) + " positions");
    }
    for (const Facet& facet : mesh.facets) {
        for (const std::uint32_t corner : facet.corners) {
            if (corner >= mesh.positions.size()) throw std::invalid_argument("mesh facet names a missing vertex");
        }
    }
}

// What the vertex stage sees of corner k of a facet, at `position` with `normal`.
inline Corner corner_of(const Mesh& mesh, const Facet& facet, std::size_t k, glm::vec3 position, glm::vec3 normal) {
    const std::uint32_t i = facet.corners[k];
    return {position, normal, mesh.uvs.empty() ? glm::vec2(0.0F) : mesh.uvs[i],
            mesh.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : mesh.colours[i]};
}

// The Varying of each corner of a facet, from the vertex stage's per-vertex results or, for
// facet normals, made here.
template <typename Shader>
std::array<typename Shader::Varying, 3> facet_varyings(const Shader& shader, const Mesh& mesh, const Facet& facet,
                                                       const std::vector<typename Shader::Varying>& per_vertex) {
    const std::array<glm::vec3, 3> at{mesh.positions[facet.corners[0]], mesh.positions[facet.corners[1]],
                                      mesh.positions[facet.corners[2]]};
    if (Shader::kFacetNormal) {  // lit once per facet at its centroid; texture coordinates and colours stay each corner's own
        const glm::vec3 centroid = at[0] / 3.0F + at[1] / 3.0F + at[2] / 3.0F;  // no overflow
        if (mesh.uvs.empty() && mesh.colours.empty()) {
            const auto shared = shader.vertex({centroid, facet.normal});
            return {shared, shared, shared};
        }
        return {shader.vertex(corner_of(mesh, facet, 0, centroid, facet.normal)), shader.vertex(corner_of(mesh, facet, 1, centroid, facet.normal)),
                shader.vertex(corner_of(mesh, facet, 2, centroid, facet.normal))};
    }
    if (mesh.surface == Surface::faceted) {  // the facet's normal, each corner's own position
        return {shader.vertex(corner_of(mesh, facet, 0, at[0], facet.normal)), shader.vertex(corner_of(mesh, facet, 1, at[1], facet.normal)),
                shader.vertex(corner_of(mesh, facet, 2, at[2], facet.normal))};
    }
    return {per_vertex[facet.corners[0]], per_vertex[facet.corners[1]], per_vertex[facet.corners[2]]};
}

// The vertex stage's Varying of vertex i, for shaders that light per vertex or per pixel.
template <typename Shader>
typename Shader::Varying vertex_varying(const Shader& shader, const Mesh& mesh, std::size_t i) {
    return shader.vertex({mesh.positions[i], mesh.normals[i], mesh.uvs.empty() ? glm::vec2(0.0F) : mesh.uvs[i],
                          mesh.colours.empty() ? LinearRgb{1.0F, 1.0F, 1.0F} : mesh.colours[i]});
}

// Whether a triangle's corners leave every pixel centre of a band of rows above or below them,
// so that drawing into that band can skip it before any shading work.
inline bool misses_rows(const std::array<SubpixelPoint, 3>& points, const PixelRect& rows) noexcept {
    const std::int32_t low = std::min({points[0].y, points[1].y, points[2].y});
    const std::int32_t high = std::max({points[0].y, points[1].y, points[2].y});
    return high < rows.y * kSubpixelOne || low > (rows.y + rows.height - 1) * kSubpixelOne;
}

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
            screen_[i] = {usable_depth ? snap_to_subpixel(camera_.screen_from_view(view)) : std::nullopt, static_cast<float>(view.z)};
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
            const std::array<SubpixelPoint, 3> points{corners[0].at, corners[1].at, corners[2].at};
            if (twice_signed_area(points) <= 0) continue;  // facing away, or seen edge-on
            ++drawn;
            const std::array<Varying, 3> values = facet_varyings(shader_, mesh_, facet, varyings_);
            for (std::size_t k = 0; k < 3; ++k) corners[k].varying = values[k];
            visit(corners);
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
