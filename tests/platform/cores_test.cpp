#include <raster/platform/cores.hpp>

#include <cstddef>
#include <thread>
#include <gtest/gtest.h>
#include <sched.h>

TEST(AvailableCores, IsAtLeastOne) { EXPECT_GE(raster::available_cores(), 1); }

TEST(AvailableCores, CountsTheCoresThisProcessMayRunOn) {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    ASSERT_EQ(::sched_getaffinity(0, sizeof allowed, &allowed), 0);
    EXPECT_EQ(raster::available_cores(), CPU_COUNT(&allowed));
}

TEST(AvailableCores, FollowsTheAffinityWhenItIsNarrowed) {
    cpu_set_t before;
    CPU_ZERO(&before);
    ASSERT_EQ(::sched_getaffinity(0, sizeof before, &before), 0);
    std::size_t one = 0;
    while (!CPU_ISSET(one, &before)) ++one;
    // Narrowed on a thread of its own, so the test's other threads keep every core.
    int seen = 0;
    std::thread narrowed([&] {
        cpu_set_t single;
        CPU_ZERO(&single);
        CPU_SET(one, &single);
        if (::sched_setaffinity(0, sizeof single, &single) == 0) seen = raster::available_cores();
    });
    narrowed.join();
    EXPECT_EQ(seen, 1);
}
