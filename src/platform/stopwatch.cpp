#include <raster/platform/stopwatch.hpp>

#include <chrono>
#include <sys/resource.h>

namespace raster {

double processor_seconds(Counted counted) noexcept {
    rusage used{};
    if (::getrusage(counted == Counted::thread ? RUSAGE_THREAD : RUSAGE_SELF, &used) != 0) return 0.0;
    return static_cast<double>(used.ru_utime.tv_sec + used.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(used.ru_utime.tv_usec + used.ru_stime.tv_usec);
}

double wall_seconds() noexcept {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Stopwatch::Stopwatch(Counted counted) noexcept : counted_(counted), at_{wall_seconds(), processor_seconds(counted)} {}

Spent Stopwatch::lap() noexcept {
    const Spent now{wall_seconds(), processor_seconds(counted_)};
    const Spent spent{now.wall - at_.wall, now.processor - at_.processor};
    at_ = now;
    return spent;
}

}  // namespace raster
