#include <raster/render/scene.hpp>

#include <raster/rasterize/draw_mesh.hpp>
#include <raster/shade/textured_shaders.hpp>

#include <raster/render/samples.hpp>

#include "camera/clipped_facets.hpp"
#include "geometry/posing.hpp"
#include "rasterize/depth_only.hpp"
#include "render/depth_first.hpp"
#include "rasterize/strip_bins.hpp"
#include "rasterize/multisample_triangle.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/worker_team.hpp"
#include "render/sample_resolve.hpp"

#include <algorithm>
#include <numeric>
#include <utility>
#include <thread>
#include <type_traits>
#include <vector>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace raster {

bool needs_depth(std::span<const SceneObject> objects) noexcept {
    std::size_t meshes = 0;
    bool convex = true;
    for (const SceneObject& object : objects) {
        if (!object.mesh) continue;
        ++meshes;
        convex = convex && object.mesh->convex;
    }
    return meshes > 1 || !convex;
}

namespace {

// Lights one object by its material and hands `draw` the shader its shading method asks for.
// `eye` is the viewer's position in perspective; orthographic views have `to_eye` alone.
template <typename Draw>
std::size_t draw_shaded(const SceneObject& object, std::span<const DirectionalLight> lights,
                        std::span<const PointLight> points, glm::vec3 to_eye, std::optional<glm::vec3> eye,
                        std::optional<DepthDarkening> darkening, Draw draw) {
    if (const auto* phase1 = std::get_if<Material>(&object.material)) {
        // Phase 1's model has one viewer direction, the camera's, even in perspective.
        const Lighting lighting(*phase1, lights, to_eye);
        switch (object.shading) {
        case ShadingMethod::flat: return draw(FlatShader{&lighting});
        case ShadingMethod::gouraud: return draw(GouraudShader{&lighting});
        case ShadingMethod::phong: return draw(PhongShader{&lighting});
        case ShadingMethod::unlit: return draw(UnlitShader{{linear_from_srgb(phase1->base)}});
        }
        return 0;
    }
    const PhongMaterial& material = std::get<PhongMaterial>(object.material);
    const LinearLighting lighting(material, lights, points, to_eye, eye, darkening);
    const DiffuseSource diffuse{material.diffuse, object.texture.get(), object.sampler};
    if (!object.mesh->colours.empty()) {  // the corners' colours interpolated to every pixel
        switch (object.shading) {
        case ShadingMethod::flat: return draw(TintedFlatShader{&lighting, diffuse});
        case ShadingMethod::gouraud: return draw(TintedGouraudShader{&lighting, diffuse});
        case ShadingMethod::unlit: return draw(TintedUnlitShader{diffuse});
        default: return draw(TintedPhongShader{&lighting, diffuse});
        }
    }
    if (object.shading == ShadingMethod::unlit) return draw(UnlitShader{diffuse});
    if (object.texture) {  // the textured shaders read the texture at every pixel
        switch (object.shading) {
        case ShadingMethod::flat: return draw(TexturedFlatShader{&lighting, diffuse});
        case ShadingMethod::gouraud: return draw(TexturedGouraudShader{&lighting, diffuse});
        default: return draw(TexturedPhongShader{&lighting, diffuse});
        }
    }
    switch (object.shading) {
    case ShadingMethod::flat: return draw(LinearFlatShader{&lighting});
    case ShadingMethod::gouraud: return draw(LinearGouraudShader{&lighting});
    default: return draw(LinearPhongShader{&lighting});
    }
}

// The threads a render uses: the count asked for, 0 meaning one per core, at most kMaxThreads.
int thread_count(int asked) {
    if (asked < 0) throw std::invalid_argument("thread count must be 0 (one per core) or more, got " + std::to_string(asked));
    const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
    return std::clamp(asked == 0 ? cores : asked, 1, kMaxThreads);
}

// Items per batch of the front end: about four batches a thread, each between these sizes, so
// that a small mesh stays on one thread (waking another costs more) and a big one is shared.
constexpr std::size_t kSmallestBatch = 2048;
constexpr std::size_t kLargestBatch = 8192;

// Clears to the background, prepares depth only when the scene needs it, and draws every object
// in three parallel steps on `team`: its vertices posed and put
// through the front end `front_for(mesh, shader)` in batches, then its facets
// likewise, each batch binned into strips of rows, then the strips, cleared on the first
// object's pass and drawn with every batch's triangles in facet order.
// Multisampling: one with `samples` draws into its sample buffer instead, at its offsets, and
// resolves every strip into the framebuffer at the end (and the coverage into `alpha`, if any).
struct Multisampling {
    detail::SampleBuffer* buffer = nullptr;
    std::span<const detail::SampleOffset> offsets{};
    std::uint8_t* alpha = nullptr;
};

template <detail::Interpolation kMode, typename Camera, typename FrontFor>
std::size_t render_objects(Framebuffer& framebuffer, const BasicScene<Camera>& scene, DepthBuffer& depth,
                           std::optional<glm::vec3> eye, detail::WorkerTeam& team, FrontFor front_for, Multisampling multisampling,
                           RenderOptions::DepthFirst order) {
    detail::SampleBuffer* const samples = multisampling.buffer;
    const bool depth_test = needs_depth(scene);
    if (depth_test && samples == nullptr) depth.resize(framebuffer.width(), framebuffer.height());  // each strip clears its own rows
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
    // One object through `shader`: posed, put through the front end, binned and drawn strip by strip.
    const auto draw_object = [&](const SceneObject& object, const auto& shader) {
        using Shader = std::remove_cvref_t<decltype(shader)>;
        const bool per_facet = Shader::kFacetNormal || object.mesh->surface == Surface::faceted;
        detail::check_drawable(framebuffer, tested, *object.mesh);  // before posing reads its facets
        detail::Posing posing(*object.mesh, object.model, {.vertex_normals = !per_facet, .facet_normals = per_facet});
        const Mesh& mesh = posing.mesh();  // sized now, filled by the batches below
        auto front = front_for(mesh, shader);
        const std::size_t vertices = mesh.positions.size(), facets = mesh.facets.size();
        const std::size_t vertex_batch = batch_size(vertices), facet_batch = batch_size(facets);
        team.for_each(batches(vertices, vertex_batch), [&](int b) {
            const auto [begin, end] = range(b, vertices, vertex_batch);
            posing.vertices(begin, end);
            front.vertices(begin, end);  // reads vertex i's posed data only
        });
        std::vector<detail::StripBins<typename Shader::Varying>> bins(static_cast<std::size_t>(batches(facets, facet_batch)),
                                                                      detail::StripBins<typename Shader::Varying>(layout, samples != nullptr ? kSubpixelOne / 2 : 0));
        std::vector<std::size_t> counted(bins.size());
        team.for_each(static_cast<int>(bins.size()), [&](int b) {
            const auto [begin, end] = range(b, facets, facet_batch);
            detail::StripBins<typename Shader::Varying>& batch = bins[static_cast<std::size_t>(b)];
            batch.reserve(end - begin);
            posing.facets(begin, end);  // facet f reads its own posed corners and normal only
            counted[static_cast<std::size_t>(b)] = front.facets(begin, end, [&](const auto& corners) { batch.add(corners); });
            batch.finish();
        });
        team.for_each(layout.count(), [&](int s) {
            const PixelRect strip = layout.strip(s);
            if (!cleared) clear(strip);
            detail::LaneBatch<Shader> lanes(shader);  // open across the strip's triangles: full batches on small ones
            for (const auto& batch : bins) {
                batch.for_each_in(s, [&](const auto& corners) {
                    if (samples != nullptr) {
                        detail::shade_triangle_samples<Shader, kMode>(*samples, depth_test, corners, shader, strip, multisampling.offsets, &lanes);
                    } else {
                        detail::shade_triangle<Shader, detail::FloatDepth, kMode>(framebuffer, tested, corners, shader, {}, strip, &lanes);
                    }
                });
            }
            lanes.flush();
        });
        cleared = true;
        return std::accumulate(counted.begin(), counted.end(), std::size_t{0});
    };
    const bool depth_pass = depth_test && (order == RenderOptions::DepthFirst::always ||
                                           (order == RenderOptions::DepthFirst::automatic &&
                                            detail::depth_first(scene, depth_test, framebuffer.width(), framebuffer.height())));
    if (depth_pass) {
        // Every object's depth first, then the shading pass colours only the fragments at the
        // nearest depth: the same picture (the last facet at that depth wins, as it would),
        // without shading the surfaces hidden behind it.
        for (const SceneObject& object : scene.objects) {
            if (object.mesh) draw_object(object, detail::DepthOnlyShader{});
        }
    }
    std::size_t drawn = 0;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;  // an object without a mesh shows nothing
        drawn += draw_shaded(object, scene.lights, scene.point_lights, to_eye, eye, scene.darkening,
                             [&](const auto& shader) { return draw_object(object, shader); });
    }
    if (!cleared) {
        team.for_each(layout.count(), [&](int s) { clear(layout.strip(s)); });
    }
    if (samples != nullptr) {
        team.for_each(layout.count(), [&](int s) {
            const PixelRect strip = layout.strip(s);
            samples->resolve_rows(strip.y, strip.y + strip.height, framebuffer, scene.background, multisampling.alpha);
        });
    }
    return drawn;
}

std::size_t draw(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth, detail::WorkerTeam& team, RenderOptions::DepthFirst order,
                 Multisampling multisampling = {}) {
    // Orthographic: attributes are linear on screen, and the direction toward the viewer is the same at every pixel.
    return render_objects<detail::Interpolation::screen_linear>(framebuffer, scene, depth, std::nullopt, team,
                                                                [&](const Mesh& mesh, const auto& shader) {
                                                                    return detail::OrthoFront(scene.camera, mesh, shader);
                                                                },
                                                                multisampling, order);
}

std::size_t draw(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth, detail::WorkerTeam& team,
                 RenderOptions::DepthFirst order, Multisampling multisampling = {}) {
    // Phase 2 takes the direction toward the eye at every point.
    return render_objects<detail::Interpolation::perspective>(
        framebuffer, scene, depth, scene.camera.eye(), team, [&](const Mesh& mesh, const auto& shader) {
            return detail::PerspectiveFront(framebuffer, scene.camera, mesh, shader, detail::kGuardBandPixels);
        },
        multisampling, order);
}

// The most memory a frame's samples may take (colour and depth, 7 bytes a sample); a frame that
// needs more is drawn pass by pass, in the memory of two frames.
constexpr std::size_t kMaxSampleBufferBytes = std::size_t{1} << 30;

// Draws the scene at `samples` per pixel into `framebuffer`; one sample is the plain draw.
// Multisampling shades once per pixel into `buffer`; supersampling (asked for, or when the
// samples of the frame would not fit in kMaxSampleBufferBytes) draws a whole pass at each
// sample position. `alpha`, for a scene that keeps depth, receives the share of samples covered.
template <typename Camera>
std::size_t draw_samples(Framebuffer& framebuffer, const BasicScene<Camera>& scene, DepthBuffer& depth, detail::WorkerTeam& team,
                         RenderOptions options, detail::SampleBuffer& buffer, std::vector<std::uint8_t>* alpha) {
    const std::span<const glm::vec2> offsets = sample_offsets(options.samples);
    if (offsets.size() == 1) return draw(framebuffer, scene, depth, team, options.depth_first);
    const std::size_t pixels = static_cast<std::size_t>(framebuffer.width()) * static_cast<std::size_t>(framebuffer.height());
    if (!options.shade_every_sample && pixels * offsets.size() * 7 <= kMaxSampleBufferBytes) {
        std::array<detail::SampleOffset, detail::kMaxSamples> at{};
        for (std::size_t s = 0; s < offsets.size(); ++s) {
            const glm::dvec2 o(offsets[s]);
            at[s] = {static_cast<std::int32_t>(std::lround(o.x * kSubpixelOne)), static_cast<std::int32_t>(std::lround(o.y * kSubpixelOne)), o.x, o.y};
        }
        buffer.resize(framebuffer.width(), framebuffer.height(), static_cast<int>(offsets.size()), scene.background);
        std::uint8_t* coverage = nullptr;
        if (alpha != nullptr && scene.keep_depth) {
            alpha->assign(pixels, 0);
            coverage = alpha->data();
        } else if (alpha != nullptr) {
            alpha->clear();  // an opaque scene has no coverage to give
        }
        return draw(framebuffer, scene, depth, team, options.depth_first, {&buffer, std::span(at.data(), offsets.size()), coverage});
    }
    // Only a caller that takes the alpha gets the surfaces' colour apart from the background.
    const bool with_alpha = alpha != nullptr && scene.keep_depth;
    if (alpha != nullptr && !with_alpha) alpha->clear();
    detail::SampleResolve resolve(framebuffer.width(), framebuffer.height(), with_alpha);
    Framebuffer pass(framebuffer.width(), framebuffer.height());
    BasicScene<Camera> moved = scene;
    std::size_t drawn = 0;
    for (const glm::vec2 offset : offsets) {
        moved.camera = scene.camera.sampled_at(glm::dvec2(offset));
        drawn = draw(pass, moved, depth, team, options.depth_first);
        if (with_alpha) {
            resolve.add(pass, depth.coverage());
        } else {
            resolve.add(pass);
        }
    }
    resolve.resolve(framebuffer, scene.background, with_alpha ? alpha : nullptr);
    return drawn;
}

}  // namespace

std::size_t render(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth, RenderOptions options) {
    (void)sample_offsets(options.samples);  // refused before any thread starts
    detail::WorkerTeam team(std::min(thread_count(options.threads), framebuffer.height()));
    detail::SampleBuffer buffer;
    return draw_samples(framebuffer, scene, depth, team, options, buffer, nullptr);
}

std::size_t render(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth, RenderOptions options) {
    (void)sample_offsets(options.samples);
    detail::WorkerTeam team(std::min(thread_count(options.threads), framebuffer.height()));
    detail::SampleBuffer buffer;
    return draw_samples(framebuffer, scene, depth, team, options, buffer, nullptr);
}

Renderer::Renderer(RenderOptions options)
    : team_(std::make_unique<detail::WorkerTeam>(thread_count(options.threads))),
      samples_buffer_(std::make_unique<detail::SampleBuffer>()),
      options_{options.threads, static_cast<int>(sample_offsets(options.samples).size()), options.shade_every_sample, options.depth_first} {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
int Renderer::threads() const noexcept { return team_->size(); }
std::size_t Renderer::render(Framebuffer& framebuffer, const Scene& scene) {
    return draw_samples(framebuffer, scene, depth_, *team_, options_, *samples_buffer_, &coverage_);
}
std::size_t Renderer::render(Framebuffer& framebuffer, const PerspectiveScene& scene) {
    return draw_samples(framebuffer, scene, depth_, *team_, options_, *samples_buffer_, &coverage_);
}
std::vector<std::uint8_t> Renderer::coverage() const { return options_.samples == 1 ? depth_.coverage() : coverage_; }

PerspectiveScene in_perspective(const Scene& scene, int width, int height, double fov_degrees) {
    if (!(fov_degrees > 0.0 && fov_degrees < 180.0)) {
        throw std::invalid_argument("field of view must be between 0 and 180 degrees, got " + std::to_string(fov_degrees));
    }
    const OrthoCamera& flat = scene.camera;
    const double to_origin = flat.view_from_world(glm::vec3(0.0F)).z;
    // Pixels per world unit match the orthographic camera's on the plane through the origin.
    const double half_angle = fov_degrees * std::numbers::pi / 360.0;
    const double distance = height / (2.0 * std::max(flat.scale(), 0.5) * std::tan(half_angle));
    const PerspectiveCamera::Lens lens{fov_degrees, distance / 100.0, distance + 100.0};
    // The same axes, the eye moved in double precision: no rounding through floats on the way.
    const OrthoCamera moved = flat.dollied(to_origin - distance);
    if (!std::isfinite(glm::length(glm::dvec3(moved.eye())))) throw std::invalid_argument("camera eye is too far out to move back");
    const PerspectiveCamera camera = PerspectiveCamera::from_view(moved, width, height, lens);
    return {camera, scene.background, scene.lights, scene.point_lights, scene.objects, scene.darkening};
}

}  // namespace raster
