// Stays whole: the depth pass, the opaque objects and the blended strips share one set of strips, buffers and bins.
#pragma once

#include <raster/render/scene.hpp>

#include "geometry/posing.hpp"
#include "rasterize/depth_only.hpp"
#include "rasterize/fragment_triangle.hpp"
#include "rasterize/multisample_triangle.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/setup_ortho.hpp"
#include "rasterize/setup_perspective.hpp"
#include "rasterize/strip_bins.hpp"
#include "rasterize/worker_team.hpp"
#include "render/depth_first.hpp"
#include "render/draw_points_lines.hpp"
#include "render/fragment_resolve.hpp"
#include "render/shader_choice.hpp"
#include "render/team_clock.hpp"

#include <algorithm>
#include <any>
#include <atomic>
#include <numeric>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

// A frame's objects drawn on a team of threads: vertices and facets in batches, binned into
// strips of rows, then the strips.
namespace raster::detail {

// Items per batch of the front end: about four batches a thread, each between these sizes, so
// that a small mesh stays on one thread (waking another costs more) and a big one is shared.
constexpr std::size_t kSmallestBatch = 2048;
constexpr std::size_t kLargestBatch = 8192;

// Clears to the background, prepares depth only when the scene needs it, and draws each object in
// three parallel steps on `team`: vertices posed and through `front_for(mesh, shader)` in batches,
// facets likewise, binned into strips of rows, then the strips, drawn in facet order.
// Multisampling: one with `samples` draws into its sample buffer instead, at its offsets, and
// resolves every strip into the framebuffer at the end (and the coverage into `alpha`, if any).
struct Multisampling {
    detail::SampleBuffer* buffer = nullptr;
    std::span<const detail::SampleOffset> offsets{};
    std::uint8_t* alpha = nullptr;
    std::vector<detail::FragmentList>* fragments = nullptr;  // a Renderer's, kept from frame to frame; else the frame's
    FrameTiming* timing = nullptr;                           // set when the frame's resolve is timed apart
};

// How an object's alpha is drawn: not at all, blended, or masked sample by sample (a mask
// without a texture or vertex alpha shows whole or not at all, and draws as an opaque object).
enum class AlphaKind { none, blend, mask };
inline AlphaKind alpha_kind_of(const SceneObject& object) noexcept {
    if (blends(object.opacity)) return AlphaKind::blend;
    const bool varies = (object.texture && object.texture->has_alpha()) || takes_vertex_alpha(object);
    return object.opacity.mode == AlphaMode::mask && varies ? AlphaKind::mask : AlphaKind::none;
}

// The surface's alpha where a Shader's Varying is that: the opacity factor times the corners' alpha and the alpha
// map, if any, read where the base colour map is read.
template <typename Shader>
auto alpha_reader(const SceneObject& object) {
    const Texture* alpha_map = object.texture && object.texture->has_alpha() ? object.texture.get() : nullptr;
    const auto* pbr = std::get_if<MetallicRoughness>(&object.material);
    const TextureTransform moved = pbr != nullptr ? pbr->base_colour_transform : TextureTransform{};
    return [=, &object](const typename Shader::Varying& varying) {  // implicit: the map goes unused without uv
        const auto& own = own_varying(varying);  // times the corners' alpha, where the shader carries it
        float alpha = object.opacity.factor * vertex_alpha_of(varying);
        if constexpr (requires { own.uv; }) {
            if (alpha_map != nullptr) alpha *= alpha_map->alpha(moved_uv(moved, own.uv, {}).uv, object.sampler.wrap);
        }
        return alpha;
    };
}

template <detail::Interpolation kMode, typename Camera, typename FrontFor>
std::size_t render_objects(Framebuffer& framebuffer, const BasicScene<Camera>& scene, DepthBuffer& depth,
                           std::optional<glm::vec3> eye, detail::WorkerTeam& team, FrontFor front_for,
                           Multisampling multisampling, RenderOptions::DepthFirst order) {
    detail::SampleBuffer* const samples = multisampling.buffer;
    const bool depth_test = needs_depth(scene);
    if (depth_test && samples == nullptr)
        depth.resize(framebuffer.width(), framebuffer.height());                      // each strip clears its own rows
    DepthBuffer* const tested = depth_test && samples == nullptr ? &depth : nullptr;  // samples keep their own depths
    const glm::vec3 to_eye = -scene.camera.direction();
    const detail::StripLayout layout = detail::StripLayout::of(framebuffer.width(), framebuffer.height());
    const auto batch_size = [&](std::size_t items) {
        const auto share = static_cast<std::size_t>(4 * team.size());
        return std::clamp((items + share - 1) / share, kSmallestBatch, kLargestBatch);
    };
    const auto batches = [](std::size_t items, std::size_t per) { return static_cast<int>((items + per - 1) / per); };
    const auto range = [](int batch, std::size_t items, std::size_t per) {
        const std::size_t begin = static_cast<std::size_t>(batch) * per;
        return std::pair{begin, std::min(items, begin + per)};
    };
    bool cleared = false;
    const auto clear = [&](const PixelRect& strip) {
        if (samples != nullptr) return samples->clear_rows(strip.y, strip.y + strip.height);
        framebuffer.clear_rows(strip.y, strip.y + strip.height, scene.background);
        if (tested != nullptr) tested->clear_rows(strip.y, strip.y + strip.height);
    };
    // Blend objects' fragments: one list a thread, each strip's gathered, resolved and forgotten in turn.
    std::vector<detail::FragmentList> own_fragments;
    std::vector<detail::FragmentList>& fragments =
        multisampling.fragments != nullptr ? *multisampling.fragments : own_fragments;
    // One object posed, put through the front end and binned into strips: its bins and the facets it counted.
    const auto bin_object = [&](const SceneObject& object, const auto& shader) {
        using Shader = std::remove_cvref_t<decltype(shader)>;
        const bool per_facet = Shader::kFacetNormal || object.mesh->surface == Surface::faceted;
        detail::Posing posing(*object.mesh, object.model, {.vertex_normals = !per_facet, .facet_normals = per_facet});
        const Mesh& mesh = posing.mesh();  // sized now, filled by the batches below
        auto front = front_for(mesh, shader);
        const std::size_t vertices = mesh.positions.size(), facets = mesh.facets.size();
        const std::size_t vertex_batch = batch_size(vertices), facet_batch = batch_size(facets);
        team.for_each(batches(vertices, vertex_batch), [&](int b) {
            const auto [begin, end] = range(b, vertices, vertex_batch);
            posing.vertices(begin, end);
            if (facets != 0) front.vertices(begin, end);  // reads vertex i's posed data only
        });
        std::vector<detail::StripBins<typename Shader::Varying>> bins(
            static_cast<std::size_t>(batches(facets, facet_batch)),
            detail::StripBins<typename Shader::Varying>(layout, samples != nullptr ? kSubpixelOne / 2 : 0));
        std::vector<std::size_t> counted(bins.size());
        team.for_each(static_cast<int>(bins.size()), [&](int b) {
            const auto [begin, end] = range(b, facets, facet_batch);
            detail::StripBins<typename Shader::Varying>& batch = bins[static_cast<std::size_t>(b)];
            batch.reserve(end - begin);
            posing.facets(begin, end);  // facet f reads its own posed corners and normal only
            counted[static_cast<std::size_t>(b)] =
                front.facets(begin, end, [&](const auto& corners) { batch.add(corners); });
            batch.finish();
        });
        return std::pair{std::move(bins), std::accumulate(counted.begin(), counted.end(), std::size_t{0})};
    };
    // An object's binned triangles drawn into strip s, in facet order; a blended one's gathered into `list`.
    const auto draw_strip = [&](const SceneObject& object, const auto& shader, const auto& bins, int s,
                                detail::FragmentList* list) {
        using Shader = std::remove_cvref_t<decltype(shader)>;
        const AlphaKind alpha_kind = DepthOnly<Shader> ? AlphaKind::none : alpha_kind_of(object);
        const auto alpha_of = alpha_reader<Shader>(object);
        const PixelRect strip = layout.strip(s);
        if (!cleared) clear(strip);
        detail::LaneBatch<Shader> lanes(shader);  // open across the strip's triangles: full batches on small ones
        for (const auto& batch : bins) {
            batch.for_each_in(s, [&](const auto& corners) {
                if (alpha_kind != AlphaKind::none) {
                    detail::gather_triangle<Shader, kMode>(
                        alpha_kind == AlphaKind::blend ? list : nullptr, {samples, tested, &framebuffer},
                        framebuffer.width(), corners, shader, alpha_of, object.opacity.cutoff, strip,
                        samples != nullptr ? multisampling.offsets : std::span(detail::kCentreOnly), lanes);
                } else if (samples != nullptr) {
                    detail::shade_triangle_samples<Shader, kMode>(*samples, depth_test, corners, shader, strip,
                                                                  multisampling.offsets, &lanes);
                } else {
                    detail::shade_triangle<Shader, detail::FloatDepth, kMode>(framebuffer, tested, corners, shader, {},
                                                                              strip, &lanes);
                }
            });
        }
        lanes.flush();
    };
    // Binned triangles of each blended object (empty: points and lines alone), drawn strip by strip at the end.
    std::vector<std::any> blended_bins;
    // One object through `shader`: binned, drawn strip by strip (kept for the strips' resolve if blended), then its
    // points and lines.
    const auto draw_object = [&](const SceneObject& object, const auto& shader) {
        using Shader = std::remove_cvref_t<decltype(shader)>;
        detail::check_drawable(framebuffer, tested, *object.mesh);  // before posing reads its facets
        const bool blended = !DepthOnly<Shader> && alpha_kind_of(object) == AlphaKind::blend;
        std::size_t counted = 0;
        if (!cleared && (blended || object.mesh->facets.empty()))  // no strip loop here to clear the strips
            team.for_each(layout.count(), [&](int s) { clear(layout.strip(s)); });
        if (object.mesh->facets.empty()) {  // points and lines alone: no posed copy, no front end
            if (blended) blended_bins.emplace_back();
        } else {
            auto binned = bin_object(object, shader);  // no structured binding: clang 14 cannot capture one
            auto& bins = binned.first;
            counted = binned.second;
            if (blended) {
                blended_bins.emplace_back(std::move(bins));
            } else {
                team.for_each(layout.count(), [&](int s) { draw_strip(object, shader, bins, s, nullptr); });
            }
        }
        cleared = true;
        if constexpr (!DepthOnly<Shader>) {  // points and lines are drawn in the shading pass only
            detail::draw_points_lines(scene.camera, scene.points_and_lines, object, shader, team, layout,
                                      {&framebuffer, tested, samples, depth_test, multisampling.offsets});
        }
        return counted;
    };
    const bool depth_pass =
        depth_test && (order == RenderOptions::DepthFirst::always ||
                       (order == RenderOptions::DepthFirst::automatic &&
                        detail::depth_first(scene, depth_test, framebuffer.width(), framebuffer.height())));
    if (depth_pass) {
        // Every object's depth first, then the shading pass colours only the fragments at the
        // nearest depth: the same picture (the last facet at that depth wins, as it would),
        // without shading the surfaces hidden behind it.
        for (const SceneObject& object : scene.objects) {
            if (object.mesh && alpha_kind_of(object) == AlphaKind::none && shows(object.opacity))
                draw_object(object, detail::DepthOnlyShader{});
        }
    }
    std::size_t drawn = 0;
    const std::shared_ptr<const Surroundings> surroundings = surroundings_for(scene);
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh || blends(object.opacity) || !shows(object.opacity)) continue;  // blended below
        drawn += draw_shaded(object, scene.lights, scene.point_lights, to_eye, eye, scene.darkening, surroundings.get(),
                             [&](const auto& shader) { return draw_object(object, shader); });
    }
    if (!cleared) {
        team.for_each(layout.count(), [&](int s) { clear(layout.strip(s)); });
    }
    const bool blending = std::any_of(scene.objects.begin(), scene.objects.end(),
                                      [](const SceneObject& o) { return o.mesh && blends(o.opacity); });
    if (blending) {  // after every opaque object (and its points and lines), so that the fragments meet them all
        for (const SceneObject& object : scene.objects) {
            if (!object.mesh || !blends(object.opacity)) continue;
            drawn += draw_shaded(object, scene.lights, scene.point_lights, to_eye, eye, scene.darkening,
                                 surroundings.get(), [&](const auto& shader) { return draw_object(object, shader); });
        }
    }
    const auto resolve_strip = [&](int s, detail::FragmentList* list) {
        const PixelRect strip = layout.strip(s);
        if (samples != nullptr)
            samples->resolve_rows(strip.y, strip.y + strip.height, framebuffer, scene.background, multisampling.alpha);
        if (list != nullptr)
            resolve_fragments(*list, {&framebuffer, samples, samples != nullptr ? nullptr : tested},
                              multisampling.alpha, strip.y, strip.y + strip.height);
    };
    if (blending && multisampling.timing != nullptr) multisampling.timing->resolve_in_draw = true;
    if (blending) {
        // Each strip's blended triangles, in the objects' order, gathered into its thread's list and resolved while
        // they are still in cache; the next strip reuses the list's memory.
        const std::size_t frame_pixels =
            static_cast<std::size_t>(framebuffer.width()) * static_cast<std::size_t>(framebuffer.height());
        fragments.resize(static_cast<std::size_t>(team.size()));
        std::atomic<int> next{0};
        team.for_each(team.size(), [&](int t) {
            detail::FragmentList& list = fragments[static_cast<std::size_t>(t)];
            for (int s = next++; s < layout.count(); s = next++) {
                const PixelRect strip = layout.strip(s);
                const std::size_t strip_pixels =
                    static_cast<std::size_t>(strip.height) * static_cast<std::size_t>(framebuffer.width());
                list.clear(kMaxFragmentBytes / sizeof(Fragment) * strip_pixels / frame_pixels,
                           static_cast<std::uint32_t>(static_cast<std::size_t>(strip.y) *
                                                      static_cast<std::size_t>(framebuffer.width())),
                           strip_pixels);
                std::size_t k = 0;
                for (const SceneObject& object : scene.objects) {
                    if (!object.mesh || !blends(object.opacity)) continue;
                    const std::any& held = blended_bins[k++];
                    if (!held.has_value()) continue;
                    draw_shaded(
                        object, scene.lights, scene.point_lights, to_eye, eye, scene.darkening, surroundings.get(),
                        [&](const auto& shader) {
                            using Bins =
                                std::vector<detail::StripBins<typename std::remove_cvref_t<decltype(shader)>::Varying>>;
                            draw_strip(object, shader, std::any_cast<const Bins&>(held), s, &list);
                            return std::size_t{0};
                        });
                }
                resolve_strip(s, &list);
            }
        });
    } else if (samples != nullptr) {
        if (multisampling.timing != nullptr) multisampling.timing->resolve.start();
        team.for_each(layout.count(), [&](int s) { resolve_strip(s, nullptr); });
        if (multisampling.timing != nullptr) multisampling.timing->resolve.stop();
    }
    return drawn;
}

inline std::size_t draw(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth, detail::WorkerTeam& team,
                        RenderOptions::DepthFirst order, Multisampling multisampling = {}) {
    // Orthographic: attributes are linear on screen, and the direction toward the viewer is the same at every pixel.
    return render_objects<detail::Interpolation::screen_linear>(
        framebuffer, scene, depth, std::nullopt, team,
        [&](const Mesh& mesh, const auto& shader) { return detail::OrthoFront(scene.camera, mesh, shader); },
        multisampling, order);
}

inline std::size_t draw(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth,
                        detail::WorkerTeam& team, RenderOptions::DepthFirst order, Multisampling multisampling = {}) {
    // Linear light takes the direction toward the eye at every point.
    return render_objects<detail::Interpolation::perspective>(
        framebuffer, scene, depth, scene.camera.eye(), team,
        [&](const Mesh& mesh, const auto& shader) {
            return detail::PerspectiveFront(framebuffer, scene.camera, mesh, shader, detail::kGuardBandPixels);
        },
        multisampling, order);
}

}  // namespace raster::detail
