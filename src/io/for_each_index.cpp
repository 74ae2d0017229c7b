#include "io/for_each_index.hpp"

#include <raster/platform/cores.hpp>

#include <algorithm>
#include <atomic>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace raster::detail {

void for_each_index(std::size_t count, std::size_t threads, const std::function<void(std::size_t)>& work) {
    std::vector<std::exception_ptr> failures(count);
    std::atomic<std::size_t> next{0};
    const auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < count;) {
            try {
                work(i);
            } catch (...) {
                failures[i] = std::current_exception();
            }
        }
    };
    {
        std::vector<std::jthread> helpers;
        helpers.reserve(std::min(threads, count));
        for (std::size_t t = 1; t < std::min(threads, count); ++t) {
            try {
                helpers.emplace_back(worker);
            } catch (const std::system_error&) {
                break;  // no room for another thread (a reader's memory cap): the ones running do the rest
            }
        }
        worker();
    }
    for (const std::exception_ptr& failure : failures) {
        if (failure) std::rethrow_exception(failure);
    }
}

std::size_t threads_or_cores(std::size_t threads) {
    return threads > 0 ? threads : static_cast<std::size_t>(available_cores());
}

}  // namespace raster::detail
