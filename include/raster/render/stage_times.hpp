#pragma once

#include <raster/platform/stopwatch.hpp>

// Where a job's time goes, stage by stage (render --timings), and how much of it ran on one core.
// Body in stage_times.cpp.
namespace raster {

// One stage's time, summed over the frames of a job.
struct StageTime {
    Spent spent;
    // Wall seconds in which at most one of the worker team's threads was busy, where counted
    // (`counted`); elsewhere the share is estimated from the wall and processor time.
    double one_core = 0.0;
    bool counted = false;

    StageTime& operator+=(const StageTime& more) noexcept {
        spent += more.spent;
        one_core += more.one_core;
        counted = counted || more.counted;
        return *this;
    }
};

// A job's stages: reading the model (in its child process, and the copy back), preparing it
// (framing, staging, each frame's scene), drawing, resolving samples, encoding and writing.
// Renderer and ModelStage add to them when given one; the program fills read and encode.
struct StageTimes {
    int threads = 1;  // the worker team's
    StageTime read, prepare, draw, resolve, encode;
    // A frame's resolve was done in its strips, inside draw (transparent surfaces): not apart.
    bool resolve_in_draw = false;
};

// The share of a stage's wall time W that ran on one core, estimated from its processor time C
// on T threads as (T*W - C) / ((T-1)*W), clamped to [0, 1]: exact only for a stage that ran
// either on one thread or on all T. 1 for one thread, 0 for no wall time.
[[nodiscard]] double estimated_one_core_share(double wall, double processor, int threads) noexcept;

// The counted share where the stage has one, else the estimate.
[[nodiscard]] double one_core_share(const StageTime& stage, int threads) noexcept;

}  // namespace raster
