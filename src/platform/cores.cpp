#include <raster/platform/cores.hpp>

#include <algorithm>
#include <thread>
#include <sched.h>

namespace raster {

int available_cores() noexcept {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    const int cores = ::sched_getaffinity(0, sizeof allowed, &allowed) == 0
                          ? CPU_COUNT(&allowed)
                          : static_cast<int>(std::thread::hardware_concurrency());
    return std::max(cores, 1);
}

}  // namespace raster
