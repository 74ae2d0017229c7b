#include <raster/platform/cores.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include "rasterize/fragment_list.hpp"
#include "rasterize/sample_buffer.hpp"
#include "rasterize/worker_team.hpp"
#include "render/draw_samples.hpp"
#include "render/team_clock.hpp"

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

// Runs draw(timing) and, when `times` is given, adds the frame's draw and resolve times to it.
template <typename Draw>
std::size_t timed_frame(detail::WorkerTeam& team, StageTimes* times, Draw draw) {
    if (times == nullptr) return draw(nullptr);
    detail::BusyThreads busy;
    team.count_busy(&busy);
    struct Stop {
        detail::WorkerTeam& team;
        ~Stop() { team.count_busy(nullptr); }
    } stop{team};
    detail::TeamClock frame(team, busy);
    detail::FrameTiming timing{detail::TeamClock(team, busy)};
    frame.start();
    const std::size_t drawn = draw(&timing);
    frame.stop();
    const StageTime& resolve = timing.resolve.total;
    StageTime drawing = frame.total;
    drawing.spent.wall -= resolve.spent.wall;
    drawing.spent.processor -= resolve.spent.processor;
    drawing.one_core -= resolve.one_core;
    times->threads = team.size();
    times->draw += drawing;
    times->resolve += resolve;
    times->resolve_in_draw = times->resolve_in_draw || timing.resolve_in_draw;
    return drawn;
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
std::size_t Renderer::render(Framebuffer& framebuffer, const Scene& scene, StageTimes* times) {
    return timed_frame(*team_, times, [&](detail::FrameTiming* timing) {
        return detail::draw_samples(framebuffer, scene, depth_, *team_, options_, *samples_buffer_, &coverage_,
                                    fragments_.get(), timing);
    });
}
std::size_t Renderer::render(Framebuffer& framebuffer, const PerspectiveScene& scene, StageTimes* times) {
    return timed_frame(*team_, times, [&](detail::FrameTiming* timing) {
        return detail::draw_samples(framebuffer, scene, depth_, *team_, options_, *samples_buffer_, &coverage_,
                                    fragments_.get(), timing);
    });
}
std::vector<std::uint8_t> Renderer::coverage() const {
    return options_.samples == 1 && coverage_.empty() ? depth_.coverage() : coverage_;  // drawn under transparency
}

}  // namespace raster
