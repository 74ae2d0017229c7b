#pragma once

#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include "render/draw_objects.hpp"
#include "render/sample_resolve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

// A frame at several samples per pixel: multisampled into a sample buffer, or supersampled
// pass by pass when asked or when the samples would not fit in memory.
namespace raster::detail {

// The most memory a frame's samples may take (colour and depth, 7 bytes a sample); a frame that
// needs more is drawn pass by pass, in the memory of two frames.
constexpr std::size_t kMaxSampleBufferBytes = std::size_t{1} << 30;

// Draws the scene at `samples` per pixel into `framebuffer`; one sample is the plain draw.
// Multisampling shades once per pixel into `buffer`; supersampling (asked for, or when the
// samples of the frame would not fit in kMaxSampleBufferBytes) draws a whole pass at each
// sample position. `alpha`, for a scene that keeps depth, receives the share of samples covered; `fragments`,
// when given, keeps the transparent fragments' memory from one frame to the next; `timing`, when given, times the
// resolve apart.
template <typename Camera>
std::size_t draw_samples(Framebuffer& framebuffer, const BasicScene<Camera>& scene, DepthBuffer& depth,
                         detail::WorkerTeam& team, RenderOptions options, detail::SampleBuffer& buffer,
                         std::vector<std::uint8_t>* alpha, std::vector<detail::FragmentList>* fragments = nullptr,
                         FrameTiming* timing = nullptr) {
    const std::span<const glm::vec2> offsets = sample_offsets(options.samples);
    const std::size_t pixels =
        static_cast<std::size_t>(framebuffer.width()) * static_cast<std::size_t>(framebuffer.height());
    const bool blending = std::any_of(scene.objects.begin(), scene.objects.end(),
                                      [](const SceneObject& o) { return o.mesh && blends(o.opacity); });
    if (offsets.size() == 1) {
        // Under transparent surfaces the depth buffer's coverage is not the alpha: the draw writes it.
        const bool composited = alpha != nullptr && scene.keep_depth && blending;
        if (alpha != nullptr) alpha->assign(composited ? pixels : 0, 0);
        return draw(framebuffer, scene, depth, team, options.depth_first,
                    {nullptr, {}, composited ? alpha->data() : nullptr, fragments, timing});
    }
    if (!options.shade_every_sample && pixels * offsets.size() * 7 <= kMaxSampleBufferBytes) {
        std::array<detail::SampleOffset, detail::kMaxSamples> at{};
        for (std::size_t s = 0; s < offsets.size(); ++s) {
            const glm::dvec2 o(offsets[s]);
            at[s] = {static_cast<std::int32_t>(std::lround(o.x * kSubpixelOne)),
                     static_cast<std::int32_t>(std::lround(o.y * kSubpixelOne)), o.x, o.y};
        }
        buffer.resize(framebuffer.width(), framebuffer.height(), static_cast<int>(offsets.size()), scene.background);
        std::uint8_t* coverage = nullptr;
        if (alpha != nullptr && scene.keep_depth) {
            alpha->assign(pixels, 0);
            coverage = alpha->data();
        } else if (alpha != nullptr) {
            alpha->clear();  // an opaque scene has no coverage to give
        }
        return draw(framebuffer, scene, depth, team, options.depth_first,
                    {&buffer, std::span(at.data(), offsets.size()), coverage, fragments, timing});
    }
    // Only a caller that takes the alpha gets the surfaces' colour apart from the background.
    const bool with_alpha = alpha != nullptr && scene.keep_depth;
    if (alpha != nullptr && !with_alpha) alpha->clear();
    detail::SampleResolve resolve(framebuffer.width(), framebuffer.height(), with_alpha);
    Framebuffer pass(framebuffer.width(), framebuffer.height());
    BasicScene<Camera> moved = scene;
    std::size_t drawn = 0;
    std::vector<std::uint8_t> pass_alpha(with_alpha && blending ? pixels : 0);
    for (const glm::vec2 offset : offsets) {
        moved.camera = scene.camera.sampled_at(glm::dvec2(offset));
        drawn = draw(pass, moved, depth, team, options.depth_first,
                     {nullptr, {}, pass_alpha.empty() ? nullptr : pass_alpha.data(), fragments, timing});
        if (timing != nullptr) timing->resolve.start();
        if (with_alpha) {
            resolve.add(pass, pass_alpha.empty() ? depth.coverage() : pass_alpha);
        } else {
            resolve.add(pass);
        }
        if (timing != nullptr) timing->resolve.stop();
    }
    if (timing != nullptr) timing->resolve.start();
    resolve.resolve(framebuffer, scene.background, with_alpha ? alpha : nullptr);
    if (timing != nullptr) timing->resolve.stop();
    return drawn;
}

}  // namespace raster::detail
