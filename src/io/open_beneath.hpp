#pragma once

#include <filesystem>

// Opening a path below a directory so that nothing outside it is reached, not even through a
// link or a directory swapped in after any check.
namespace raster::detail {

enum class BeneathResolution {
    kernel_first,    // openat2's RESOLVE_BENEATH, or the walk where the kernel lacks it (ENOSYS, EPERM)
    component_walk,  // the walk only: what a kernel before 5.6, or a sandbox hiding openat2, gets
};

// An O_PATH descriptor for `relative` below the open `directory`, following no link: a path
// whose `..` climbs above the directory fails with EXDEV, a link on the way with ELOOP, before
// anything is reached; else -1 with errno as open(2) sets it. The walk opens one component at a
// time from `directory`, each directory with O_PATH | O_NOFOLLOW and checked as one by its
// descriptor. Nothing is opened for reading: the caller checks the kind first.
[[nodiscard]] int open_beneath(int directory, const std::filesystem::path& relative, BeneathResolution resolution);

}  // namespace raster::detail
