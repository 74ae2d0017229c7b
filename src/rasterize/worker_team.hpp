#pragma once

#include "rasterize/busy_threads.hpp"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>
#include <pthread.h>
#include <time.h>

// Threads that stay for one render and take each of its parallel steps together (posing,
// vertices, facets, strips), so that a step costs a wake-up rather than a thread's creation.
namespace raster::detail {

class WorkerTeam {
public:
    // `threads` counts the caller, who works too: 1 makes a team of one, with no helpers.
    explicit WorkerTeam(int threads) {
        for (int t = 1; t < threads; ++t) helpers_.emplace_back([this] { help(); });
    }
    ~WorkerTeam() {
        {
            const std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        start_.notify_all();
    }
    WorkerTeam(const WorkerTeam&) = delete;
    WorkerTeam& operator=(const WorkerTeam&) = delete;

    [[nodiscard]] int size() const noexcept { return static_cast<int>(helpers_.size()) + 1; }

    // While set, each step tells `busy` when its threads begin and end their turns; the caller
    // counts as busy outside the steps. Set and cleared between steps.
    void count_busy(BusyThreads* busy) {
        const std::lock_guard lock(mutex_);
        busy_ = busy;
    }

    // Processor seconds (user and system) of the team: the calling thread's and every helper's.
    [[nodiscard]] double processor_seconds() noexcept {
        double seconds = thread_seconds(CLOCK_THREAD_CPUTIME_ID);
        for (std::jthread& helper : helpers_) {
            clockid_t clock{};
            if (::pthread_getcpuclockid(helper.native_handle(), &clock) == 0) seconds += thread_seconds(clock);
        }
        return seconds;
    }

    // Runs work(i) once for every i in [0, count), each thread taking the next i not yet taken,
    // and returns when all are done; the first exception is rethrown then.
    template <typename Work>
    void for_each(int count, Work&& work) {
        if (helpers_.empty() || count <= 1) {
            for (int i = 0; i < count; ++i) work(i);
            return;
        }
        {
            const std::lock_guard lock(mutex_);
            job_ = [&work](int i) { work(i); };
            count_ = count;
            next_ = 0;
            running_ = static_cast<int>(helpers_.size());
            failure_ = nullptr;
            ++generation_;
        }
        start_.notify_all();
        take_turns();
        if (busy_ != nullptr) busy_->ended();
        std::unique_lock lock(mutex_);
        done_.wait(lock, [this] { return running_ == 0; });
        if (busy_ != nullptr) busy_->began();
        job_ = nullptr;
        if (failure_) std::rethrow_exception(failure_);
    }

private:
    static double thread_seconds(clockid_t clock) noexcept {
        timespec at{};
        if (::clock_gettime(clock, &at) != 0) return 0.0;
        return static_cast<double>(at.tv_sec) + 1e-9 * static_cast<double>(at.tv_nsec);
    }

    void take_turns() {
        for (int i = next_.fetch_add(1); i < count_; i = next_.fetch_add(1)) {
            try {
                job_(i);
            } catch (...) {
                const std::lock_guard lock(mutex_);
                if (!failure_) failure_ = std::current_exception();
                next_ = count_;  // the others stop at their next turn
            }
        }
    }

    void help() {
        std::uint64_t seen = 0;
        std::unique_lock lock(mutex_);
        for (;;) {
            start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            BusyThreads* const busy = busy_;
            lock.unlock();
            if (busy != nullptr) busy->began();
            take_turns();
            if (busy != nullptr) busy->ended();
            lock.lock();
            if (--running_ == 0) done_.notify_one();
        }
    }

    std::mutex mutex_;
    std::condition_variable start_;
    std::condition_variable done_;
    std::function<void(int)> job_;
    int count_ = 0;
    std::atomic<int> next_{0};
    int running_ = 0;  // helpers still in the current step
    std::uint64_t generation_ = 0;
    bool stopping_ = false;
    std::exception_ptr failure_;
    BusyThreads* busy_ = nullptr;        // set between steps, read under mutex_
    std::vector<std::jthread> helpers_;  // last: joined before what they read goes
};

}  // namespace raster::detail
