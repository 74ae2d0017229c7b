#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

// A fixed set of worker threads taking tasks in the order given: what the parallel animation
// encoder runs its frames on. Workers start once, so no frame pays for a thread's creation.
namespace raster::detail {

template <typename Result>
class TaskPool {
public:
    explicit TaskPool(std::size_t threads) {
        for (std::size_t i = 0; i < threads; ++i) workers_.emplace_back([this] { work(); });
    }
    ~TaskPool() {
        {
            const std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        ready_.notify_all();
        workers_.clear();  // joins, after the queue has run dry
    }
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    template <typename Function>
    std::future<Result> submit(Function&& function) {
        std::packaged_task<Result()> task(std::forward<Function>(function));
        std::future<Result> result = task.get_future();
        {
            const std::lock_guard lock(mutex_);
            queue_.push_back(std::move(task));
        }
        ready_.notify_one();
        return result;
    }

private:
    void work() {
        for (;;) {
            std::packaged_task<Result()> task;
            {
                std::unique_lock lock(mutex_);
                ready_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
                if (queue_.empty()) return;  // stopping, and nothing left to do
                task = std::move(queue_.front());
                queue_.pop_front();
            }
            task();  // an exception is kept in the task's future
        }
    }

    std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<std::packaged_task<Result()>> queue_;
    bool stopping_ = false;
    std::vector<std::jthread> workers_;  // last: joined before the queue they read goes
};

}  // namespace raster::detail
