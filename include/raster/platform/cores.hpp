#pragma once

// How many threads are worth running at once. Wherever the library or its programs take a
// thread count (RenderOptions::threads, AnimationSettings::threads, --threads), 0 means
// available_cores(). Body in cores.cpp.
namespace raster {

// The cores this process may run on: its CPU affinity (so taskset, cgroups and containers are
// heeded), else std::thread::hardware_concurrency(); at least 1.
[[nodiscard]] int available_cores() noexcept;

}  // namespace raster
