#pragma once

#include <raster/platform/stopwatch.hpp>
#include <raster/render/stage_times.hpp>

#include "rasterize/busy_threads.hpp"
#include "rasterize/worker_team.hpp"

// A stage's time on a worker team over one span or several: wall, the team's processor time and
// the wall in which at most one of its threads was busy (render --timings).
namespace raster::detail {

class TeamClock {
public:
    TeamClock(WorkerTeam& team, BusyThreads& busy) noexcept : team_(team), busy_(busy) {}

    void start() { at_ = now(); }
    void stop() {
        const Reading end = now();
        total.spent += Spent{end.wall - at_.wall, end.processor - at_.processor};
        total.one_core += end.one_core - at_.one_core;
    }

    StageTime total{{}, 0.0, true};

private:
    struct Reading {
        double wall = 0.0, processor = 0.0, one_core = 0.0;
    };
    Reading now() { return {wall_seconds(), team_.processor_seconds(), busy_.one_core_seconds()}; }

    WorkerTeam& team_;
    BusyThreads& busy_;
    Reading at_;
};

// What a timed frame's drawing tells apart: its resolve, where it has one of its own.
struct FrameTiming {
    TeamClock resolve;
    bool resolve_in_draw = false;  // resolved strip by strip with the drawing (transparent surfaces)
};

}  // namespace raster::detail
