#pragma once

// Wall-clock and processor time spent, for the timings of a job's stages (render --timings).
// Body in stopwatch.cpp.
namespace raster {

// Seconds of wall-clock time and of processor time (user and system, summed over threads).
struct Spent {
    double wall = 0.0;
    double processor = 0.0;

    Spent& operator+=(const Spent& more) noexcept {
        wall += more.wall;
        processor += more.processor;
        return *this;
    }
};

// Whose processor time is counted: every thread of the process, or the calling thread alone
// (which leaves out threads that work meanwhile for something else).
enum class Counted { process, thread };

// Processor seconds (user and system) used so far (getrusage).
[[nodiscard]] double processor_seconds(Counted counted) noexcept;
// Seconds on the steady clock, from an arbitrary start.
[[nodiscard]] double wall_seconds() noexcept;

// Wall and processor time since it started or since its last lap; it reads the clocks then only.
class Stopwatch {
public:
    explicit Stopwatch(Counted counted = Counted::process) noexcept;
    // The time since the start or the last lap; the next lap begins now.
    Spent lap() noexcept;

private:
    Counted counted_;
    Spent at_;
};

}  // namespace raster
