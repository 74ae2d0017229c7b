#include <raster/platform/cores.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include "rasterize/fragment_list.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/worker_team.hpp"
#include "render/draw_samples.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace raster {

namespace {

// The threads a render uses: the count asked for, 0 meaning one per core, at most kMaxThreads.
int thread_count(int asked) {
    if (asked < 0)
        throw std::invalid_argument("thread count must be 0 (one per core) or more, got " + std::to_string(asked));
    const int cores = available_cores();
    return std::clamp(asked == 0 ? cores : asked, 1, kMaxThreads);
}

}  // namespace

std::size_t render(Framebuffer& framebuffer, const Scene& scene, DepthBuffer& depth, RenderOptions options) {
    (void)sample_offsets(options.samples);  // refused before any thread starts
    detail::WorkerTeam team(std::min(thread_count(options.threads), framebuffer.height()));
    detail::SampleBuffer buffer;
    return detail::draw_samples(framebuffer, scene, depth, team, options, buffer, nullptr);
}

std::size_t render(Framebuffer& framebuffer, const PerspectiveScene& scene, DepthBuffer& depth, RenderOptions options) {
    (void)sample_offsets(options.samples);
    detail::WorkerTeam team(std::min(thread_count(options.threads), framebuffer.height()));
    detail::SampleBuffer buffer;
    return detail::draw_samples(framebuffer, scene, depth, team, options, buffer, nullptr);
}

Renderer::Renderer(RenderOptions options)
    : team_(std::make_unique<detail::WorkerTeam>(thread_count(options.threads))),
      samples_buffer_(std::make_unique<detail::SampleBuffer>()),
      fragments_(std::make_unique<std::vector<detail::FragmentList>>()),
      options_{options.threads, static_cast<int>(sample_offsets(options.samples).size()), options.shade_every_sample,
               options.depth_first} {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
int Renderer::threads() const noexcept { return team_->size(); }
std::size_t Renderer::render(Framebuffer& framebuffer, const Scene& scene) {
    return detail::draw_samples(framebuffer, scene, depth_, *team_, options_, *samples_buffer_, &coverage_,
                                fragments_.get());
}
std::size_t Renderer::render(Framebuffer& framebuffer, const PerspectiveScene& scene) {
    return detail::draw_samples(framebuffer, scene, depth_, *team_, options_, *samples_buffer_, &coverage_,
                                fragments_.get());
}
std::vector<std::uint8_t> Renderer::coverage() const {
    return options_.samples == 1 && coverage_.empty() ? depth_.coverage() : coverage_;  // drawn under transparency
}

}  // namespace raster
