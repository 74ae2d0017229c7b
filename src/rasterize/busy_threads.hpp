#pragma once

#include <chrono>
#include <mutex>

// The wall-clock time in which at most one thread of a worker team is busy: the serial part of
// a span of work, counted rather than estimated (render --timings).
namespace raster::detail {

class BusyThreads {
public:
    // The thread that makes it is busy from now on.
    BusyThreads() noexcept : since_(std::chrono::steady_clock::now()) {}

    void began() { change(+1); }
    void ended() { change(-1); }
    // Seconds with at most one thread busy since it was made.
    [[nodiscard]] double one_core_seconds() {
        change(0);
        const std::lock_guard lock(mutex_);
        return one_core_;
    }

private:
    void change(int by) {
        const std::lock_guard lock(mutex_);
        const auto now = std::chrono::steady_clock::now();  // read under the lock, so intervals never run backward
        if (busy_ <= 1) one_core_ += std::chrono::duration<double>(now - since_).count();
        since_ = now;
        busy_ += by;
    }

    std::mutex mutex_;
    int busy_ = 1;
    std::chrono::steady_clock::time_point since_;
    double one_core_ = 0.0;
};

}  // namespace raster::detail
