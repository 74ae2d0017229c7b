// Work split by index over threads: every index once, the lowest failure rethrown, and the work
// done by the threads that run when no more can start (src/io/for_each_index.hpp).
#include "io/for_each_index.hpp"

#include "support/sanitizers.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

TEST(ForEachIndex, EveryIndexRunsOnceAndTheLowestFailureIsRethrown) {
    std::vector<std::atomic<int>> runs(100);
    EXPECT_THROW(
        {
            try {
                raster::detail::for_each_index(runs.size(), 4, [&](std::size_t i) {
                    ++runs[i];
                    if (i == 97 || i == 31 || i == 64) throw std::runtime_error(std::to_string(i));
                });
            } catch (const std::runtime_error& failure) {
                EXPECT_STREQ(failure.what(), "31");
                throw;
            }
        },
        std::runtime_error);
    for (const std::atomic<int>& count : runs) EXPECT_EQ(count.load(), 1);
}

TEST(ForEachIndex, TheWorkIsDoneWhenNoThreadCanStart) {
#ifdef RASTER_TEST_ASAN
    GTEST_SKIP() << "the address sanitizer's shadow memory needs the address space this test takes away";
#else
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // The address space this process holds, and 2 MiB more: no thread's 8 MiB stack fits.
        std::ifstream statm("/proc/self/statm");
        unsigned long pages = 0;
        statm >> pages;
        const rlim_t cap = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE)) + (2U << 20);
        const rlimit limit{cap, cap};
        if (::setrlimit(RLIMIT_AS, &limit) != 0) std::_Exit(3);
        std::vector<int> runs(64, 0);
        try {
            raster::detail::for_each_index(runs.size(), 8, [&](std::size_t i) { ++runs[i]; });
        } catch (...) {
            std::_Exit(2);
        }
        for (const int count : runs) {
            if (count != 1) std::_Exit(1);
        }
        std::_Exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: an index ran not once; 2: it threw; 3: no limit could be set";
#endif
}
