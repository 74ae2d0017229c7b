#pragma once

#include <raster/render/scene.hpp>

#include "rasterize/item_bins.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/splat.hpp"
#include "rasterize/strip_sorted.hpp"
#include "rasterize/wide_line.hpp"
#include "rasterize/worker_team.hpp"
#include "render/point_colour.hpp"
#include "render/point_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <vector>

// One object's points and segments drawn on a team of threads, after its facets and into the
// same colour and depth (or samples): moved by the model matrix one vertex at a time (no posed
// copy), projected and coloured in batches, binned into the strips of rows, then drawn strip by
// strip in their order, so any thread count gives the same picture.
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

// Points per batch of splats, and batches a thread per round: a big cloud is drawn in rounds
// whose buffers stay in cache and are reused, so its memory does not grow with the cloud.
constexpr std::size_t kSplatBatch = 16384;
constexpr int kSplatBatchesPerThread = 8;

// draw_splat_samples' box holds the pixel of a splat's centre only for radii of half a pixel or more.
static_assert(kMinPointSize >= 1.0);

// Splats whose pixels are fetched ahead of drawing: enough to cover a wait on memory.
constexpr std::size_t kSplatsAhead = 16;

// Asks the cache for the pixel holding a splat's centre, where its samples (and depth) lie.
inline void prefetch_splat(const PointTargets& target, const Splat& splat, const PixelRect& strip) noexcept {
    const int x = std::clamp(pixel_holding(splat.x), 0, strip.width - 1);
    const int y = std::clamp(pixel_holding(splat.y), strip.y, strip.y + strip.height - 1);
    if (target.samples != nullptr) {
        // A small splat reaches the rows either side of its own.
        for (int row = std::max(y - 1, strip.y); row <= std::min(y + 1, strip.y + strip.height - 1); ++row)
            target.samples->prefetch(x, row);
    } else {
        __builtin_prefetch(
            target.framebuffer->pixels() +
            (static_cast<std::size_t>(y) * static_cast<std::size_t>(strip.width) + static_cast<std::size_t>(x)) * 3);
        if (target.depth != nullptr) __builtin_prefetch(target.depth->row(y) + x);
    }
}

// Points whose screen box sizes a cloud's splats: every point of a cloud under twice this many,
// else every k-th, at least this many; a scan's even sample spans its whole box to a pixel.
constexpr std::size_t kSizingPoints = std::size_t{1} << 20;

// The splat diameter for `source`'s points: the scene's, or sized from their box on screen.
template <typename Camera>
double point_size(const PointProjection<Camera>& projection, const PointsAndLines& style, const Mesh& source,
                  const VertexPose& pose, WorkerTeam& team) {
    if (style.point_size) return *style.point_size;
    struct Box {
        double low_x = std::numeric_limits<double>::infinity(), low_y = low_x;
        double high_x = -low_x, high_y = -low_x;
        std::size_t seen = 0;
    };
    const std::size_t points = source.points.size(), step = std::max<std::size_t>(points / kSizingPoints, 1);
    const std::size_t count = (points + step - 1) / step, per = point_batch(count, team.size());
    std::vector<Box> boxes((count + per - 1) / per);
    team.for_each(static_cast<int>(boxes.size()), [&](int b) {
        Box& box = boxes[static_cast<std::size_t>(b)];
        const std::size_t begin = static_cast<std::size_t>(b) * per, end = std::min(count, begin + per);
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t i = source.points[k * step];
            const std::optional<ScreenPoint> p = projection.point(pose.position(source.positions[i]));
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
    // The sample's share in front of the camera, of the whole cloud.
    const auto seen =
        step == 1 ? all.seen
                  : static_cast<std::size_t>(std::llround(static_cast<double>(all.seen) * static_cast<double>(points) /
                                                          static_cast<double>(count)));
    return automatic_point_size((all.high_x - all.low_x) * (all.high_y - all.low_y), seen);
}

// Draws the object's points and segments, its vertices moved by its model matrix (vertex
// normals as posed() moves them), coloured by `shader` as PointColour says. Throws
// std::invalid_argument for sizes out of range or indices out of bounds, before drawing anything.
template <typename Camera, typename Shader>
void draw_points_lines(const Camera& camera, const PointsAndLines& style, const SceneObject& object,
                       const Shader& shader, WorkerTeam& team, const StripLayout& layout, const PointTargets& target) {
    const Mesh& source = *object.mesh;
    if (source.points.empty() && source.segments.empty()) return;
    check_points_and_lines(style);
    check_points_lines(source);
    const PointProjection<Camera> projection(camera);
    const PointColour<Shader> colour(shader, object);
    const VertexPose pose(object.model);
    const bool sampled = target.samples != nullptr;
    const double reach = sampled ? 0.5 : 0.0;  // samples lie up to half a pixel from their pixel's centre
    const int width = layout.width;

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
            const glm::vec3 at_i = pose.position(source.positions[i]), at_j = pose.position(source.positions[j]);
            const std::optional<ScreenSegment> s = projection.segment(at_i, at_j);
            if (!s) continue;
            const LinearRgb ci = colour.linear(posed_corner(source, pose, i, at_i));
            const LinearRgb cj = colour.linear(posed_corner(source, pose, j, at_j));
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
    if (!lines.empty()) {
        team.for_each(layout.count(), [&](int s) {
            const PixelRect strip = layout.strip(s);
            const auto line_width = static_cast<float>(style.line_width);
            for (const ItemBins<WideLine>& bins : lines) {
                bins.for_each_in(s, [&](const WideLine& line) {
                    if (sampled) {
                        draw_wide_line_samples(*target.samples, target.depth_test, line, line_width, strip,
                                               target.offsets);
                    } else {
                        draw_wide_line(*target.framebuffer, target.depth, line, line_width, strip);
                    }
                });
            }
        });
    }

    // Splats after every line, in rounds of batches: each strip meets them in the order of the points.
    const std::size_t points = source.points.size();
    if (points == 0) return;
    const double radius = point_size(projection, style, source, pose, team) / 2.0;
    const auto splat_radius = static_cast<float>(radius);
    const double spread =
        sampled ? sample_spread(target.offsets.first(std::min<std::size_t>(target.offsets.size(), kMaxSamples))) : 0.0;
    const std::size_t batches = (points + kSplatBatch - 1) / kSplatBatch;
    std::vector<StripSorted<Splat>> round(
        std::min(batches, static_cast<std::size_t>(kSplatBatchesPerThread) * static_cast<std::size_t>(team.size())),
        StripSorted<Splat>(layout));
    for (std::size_t first = 0; first < batches; first += round.size()) {
        const std::size_t count = std::min(round.size(), batches - first);
        team.for_each(static_cast<int>(count), [&](int b) {
            StripSorted<Splat>& bins = round[static_cast<std::size_t>(b)];
            const std::size_t begin = (first + static_cast<std::size_t>(b)) * kSplatBatch;
            const std::size_t end = std::min(points, begin + kSplatBatch);
            bins.refill(end - begin);
            for (std::size_t k = begin; k < end; ++k) {
                const std::uint32_t i = source.points[k];
                const glm::vec3 at = pose.position(source.positions[i]);
                const std::optional<ScreenPoint> p = projection.point(at);
                if (!p || p->x < -radius - 1.0 || p->x > width + radius + 1.0) continue;  // off the image
                const Splat splat{static_cast<float>(p->x), static_cast<float>(p->y),
                                  projection.nearer(p->depth, radius), colour.srgb(posed_corner(source, pose, i, at))};
                bins.add(splat, p->y - radius - reach, p->y + radius + reach);
            }
            bins.finish();
        });
        team.for_each(layout.count(), [&](int s) {
            const PixelRect strip = layout.strip(s);
            with_sample_count(sampled ? target.offsets.size() : 1, [&](auto samples) {
                for (std::size_t b = 0; b < count; ++b) {
                    const std::span<const Splat> splats = round[b].in(s);
                    for (std::size_t k = 0; k < splats.size(); ++k) {
                        if (k + kSplatsAhead < splats.size()) prefetch_splat(target, splats[k + kSplatsAhead], strip);
                        if (sampled) {
                            draw_splat_samples<samples()>(*target.samples, target.depth_test, splats[k], splat_radius,
                                                          spread, strip, target.offsets);
                        } else {
                            draw_splat(*target.framebuffer, target.depth, splats[k], splat_radius, strip);
                        }
                    }
                }
            });
        });
    }
}

}  // namespace raster::detail
