#pragma once

#include <raster/render/scene.hpp>

#include "rasterize/item_bins.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/splat.hpp"
#include "rasterize/wide_line.hpp"
#include "rasterize/worker_team.hpp"
#include "render/point_colour.hpp"
#include "render/point_projection.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

// One object's points and segments drawn on a team of threads, after its facets and into the
// same colour and depth (or samples): projected and coloured in batches, binned into the strips
// of rows, then drawn strip by strip in their order, so any thread count gives the same picture.
namespace raster::detail {

// Where a frame draws: its pixels (and depth, when tested), or its samples.
struct PointTargets {
    Framebuffer* framebuffer;
    DepthBuffer* depth;  // null: not tested at one sample
    SampleBuffer* samples;
    bool depth_test;
    std::span<const SampleOffset> offsets;
};

// Throws std::invalid_argument for a point or segment naming a vertex the mesh lacks.
inline void check_points_lines(const Mesh& mesh) {
    const std::size_t count = mesh.positions.size();
    for (const std::uint32_t i : mesh.points) {
        if (i >= count) throw std::invalid_argument("mesh point names a missing vertex");
    }
    for (const auto& segment : mesh.segments) {
        if (segment[0] >= count || segment[1] >= count)
            throw std::invalid_argument("mesh segment names a missing vertex");
    }
}

// Points or segments per batch: a few batches a thread, none too small to be worth a thread.
inline std::size_t point_batch(std::size_t items, int threads) noexcept {
    const auto share = static_cast<std::size_t>(4 * threads);
    return std::clamp((items + share - 1) / share, std::size_t{4096}, std::size_t{1} << 18);
}

// The splat diameter for `source`'s points: the scene's, or sized from their box on screen.
template <typename Camera>
double point_size(const PointProjection<Camera>& projection, const PointsAndLines& style, const Mesh& source,
                  const Mesh& posed, WorkerTeam& team) {
    if (style.point_size) return *style.point_size;
    struct Box {
        double low_x = std::numeric_limits<double>::infinity(), low_y = low_x;
        double high_x = -low_x, high_y = -low_x;
        std::size_t seen = 0;
    };
    const std::size_t count = source.points.size(), per = point_batch(count, team.size());
    std::vector<Box> boxes((count + per - 1) / per);
    team.for_each(static_cast<int>(boxes.size()), [&](int b) {
        Box& box = boxes[static_cast<std::size_t>(b)];
        const std::size_t begin = static_cast<std::size_t>(b) * per, end = std::min(count, begin + per);
        for (std::size_t k = begin; k < end; ++k) {
            const std::optional<ScreenPoint> p = projection.point(posed.positions[source.points[k]]);
            if (!p) continue;
            box.low_x = std::min(box.low_x, p->x), box.high_x = std::max(box.high_x, p->x);
            box.low_y = std::min(box.low_y, p->y), box.high_y = std::max(box.high_y, p->y);
            ++box.seen;
        }
    });
    Box all;
    for (const Box& box : boxes) {
        all.low_x = std::min(all.low_x, box.low_x), all.high_x = std::max(all.high_x, box.high_x);
        all.low_y = std::min(all.low_y, box.low_y), all.high_y = std::max(all.high_y, box.high_y);
        all.seen += box.seen;
    }
    if (all.seen == 0) return kMinPointSize;
    return automatic_point_size((all.high_x - all.low_x) * (all.high_y - all.low_y), all.seen);
}

// Draws `source`'s points and segments over `posed` (its vertices in the world, with vertex
// normals), coloured by `shader` as PointColour says. Throws std::invalid_argument for sizes out
// of range or indices out of bounds, before drawing anything.
template <typename Camera, typename Shader>
void draw_points_lines(const Camera& camera, const PointsAndLines& style, const SceneObject& object, const Mesh& posed,
                       const Shader& shader, WorkerTeam& team, const StripLayout& layout, const PointTargets& target) {
    const Mesh& source = *object.mesh;
    if (source.points.empty() && source.segments.empty()) return;
    check_points_and_lines(style);
    check_points_lines(source);
    const PointProjection<Camera> projection(camera);
    const PointColour<Shader> colour(shader, object);
    const bool sampled = target.samples != nullptr;
    const double reach = sampled ? 0.5 : 0.0;  // samples lie up to half a pixel from their pixel's centre
    const int width = layout.width;

    const double radius = point_size(projection, style, source, posed, team) / 2.0;
    const std::size_t points = source.points.size(), per_point = point_batch(points, team.size());
    std::vector<ItemBins<Splat>> splats((points + per_point - 1) / per_point, ItemBins<Splat>(layout));
    team.for_each(static_cast<int>(splats.size()), [&](int b) {
        ItemBins<Splat>& bins = splats[static_cast<std::size_t>(b)];
        const std::size_t begin = static_cast<std::size_t>(b) * per_point, end = std::min(points, begin + per_point);
        bins.reserve(end - begin);
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = source.points[k];
            const std::optional<ScreenPoint> p = projection.point(posed.positions[i]);
            if (!p || p->x < -radius - 1.0 || p->x > width + radius + 1.0) continue;  // off the image
            const Splat splat{static_cast<float>(p->x), static_cast<float>(p->y), projection.nearer(p->depth, radius),
                              colour.srgb(posed, i)};
            bins.add(splat, p->y - radius - reach, p->y + radius + reach);
        }
        bins.finish();
    });

    const double half_width = style.line_width / 2.0;
    const std::size_t segments = source.segments.size(), per_segment = point_batch(segments, team.size());
    std::vector<ItemBins<WideLine>> lines((segments + per_segment - 1) / per_segment, ItemBins<WideLine>(layout));
    team.for_each(static_cast<int>(lines.size()), [&](int b) {
        ItemBins<WideLine>& bins = lines[static_cast<std::size_t>(b)];
        const std::size_t begin = static_cast<std::size_t>(b) * per_segment;
        const std::size_t end = std::min(segments, begin + per_segment);
        bins.reserve(end - begin);
        for (std::size_t k = begin; k < end; ++k) {
            const auto [i, j] = source.segments[k];
            const std::optional<ScreenSegment> s = projection.segment(posed.positions[i], posed.positions[j]);
            if (!s) continue;
            const LinearRgb ci = colour.linear(posed, i), cj = colour.linear(posed, j);
            const WideLine line{s->a.x,
                                s->a.y,
                                s->b.x,
                                s->b.y,
                                projection.nearer(s->a.depth, half_width),
                                projection.nearer(s->b.depth, half_width),
                                ci + (cj - ci) * static_cast<float>(s->t_a),
                                ci + (cj - ci) * static_cast<float>(s->t_b),
                                PointProjection<Camera>::kPerspective};
            const Capsule capsule(line, half_width);
            bins.add(line, capsule.top(reach), capsule.bottom(reach));
        }
        bins.finish();
    });

    const auto splat_radius = static_cast<float>(radius);
    team.for_each(layout.count(), [&](int s) {
        const PixelRect strip = layout.strip(s);
        for (const ItemBins<WideLine>& bins : lines) {
            bins.for_each_in(s, [&](const WideLine& line) {
                const auto line_width = static_cast<float>(style.line_width);
                if (sampled) {
                    draw_wide_line_samples(*target.samples, target.depth_test, line, line_width, strip, target.offsets);
                } else {
                    draw_wide_line(*target.framebuffer, target.depth, line, line_width, strip);
                }
            });
        }
        for (const ItemBins<Splat>& bins : splats) {
            bins.for_each_in(s, [&](const Splat& splat) {
                if (sampled) {
                    draw_splat_samples(*target.samples, target.depth_test, splat, splat_radius, strip, target.offsets);
                } else {
                    draw_splat(*target.framebuffer, target.depth, splat, splat_radius, strip);
                }
            });
        }
    });
}

}  // namespace raster::detail
