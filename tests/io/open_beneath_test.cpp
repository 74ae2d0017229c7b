// Opening below a directory, by the kernel's openat2 and by the walk older kernels get.
#include "io/open_beneath.hpp"

#include "support/scratch.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using raster::detail::BeneathResolution;
using raster::detail::open_beneath;
using test_support::ScratchDir;
namespace fs = std::filesystem;

namespace {

constexpr BeneathResolution kBoth[] = {BeneathResolution::kernel_first, BeneathResolution::component_walk};

const char* name_of(BeneathResolution resolution) {
    return resolution == BeneathResolution::kernel_first ? "openat2" : "walk";
}

ino_t inode_of(const fs::path& path) {
    struct stat status {};
    EXPECT_EQ(::stat(path.c_str(), &status), 0) << path;
    return status.st_ino;
}

// The inode `relative` opens to below `directory`, or 0 with the errno it failed with.
struct Opened {
    ino_t inode = 0;
    int error = 0;
};
Opened open_below(int directory, const fs::path& relative, BeneathResolution resolution) {
    const int descriptor = open_beneath(directory, relative, resolution);
    if (descriptor < 0) return {0, errno};
    struct stat status {};
    ::fstat(descriptor, &status);
    ::close(descriptor);
    return {status.st_ino, 0};
}

// The jail: jail/sub/file inside, outside/file beside it.
class Jail {
public:
    Jail() {
        fs::create_directories(dir_ / "jail" / "sub");
        fs::create_directories(dir_ / "outside");
        test_support::write_text(dir_ / "jail" / "sub" / "file", "inside");
        test_support::write_text(dir_ / "jail" / "top", "top");
        test_support::write_text(dir_ / "outside" / "file", "outside");
        descriptor_ = ::open((dir_ / "jail").c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
    }
    ~Jail() { ::close(descriptor_); }
    Jail(const Jail&) = delete;
    Jail& operator=(const Jail&) = delete;

    [[nodiscard]] int descriptor() const { return descriptor_; }
    [[nodiscard]] fs::path operator/(const std::string& name) const { return dir_ / name; }

private:
    ScratchDir dir_;
    int descriptor_ = -1;
};

}  // namespace

TEST(OpenBeneath, DotDotResolvesByNameAndNeverClimbsAboveTheDirectory) {
    const Jail jail;
    for (const BeneathResolution resolution : kBoth) {
        SCOPED_TRACE(name_of(resolution));
        EXPECT_EQ(open_below(jail.descriptor(), "sub/file", resolution).inode, inode_of(jail / "jail/sub/file"));
        EXPECT_EQ(open_below(jail.descriptor(), "sub/../top", resolution).inode, inode_of(jail / "jail/top"));
        EXPECT_EQ(open_below(jail.descriptor(), "./sub/./file", resolution).inode, inode_of(jail / "jail/sub/file"));
        for (const char* escaping : {"../outside/file", "sub/../../outside/file", "sub/../../jail/top", ".."}) {
            EXPECT_EQ(open_below(jail.descriptor(), escaping, resolution).error, EXDEV) << escaping;
        }
        EXPECT_EQ(open_below(jail.descriptor(), jail / "outside/file", resolution).error, EXDEV) << "an absolute path";
        EXPECT_EQ(open_below(jail.descriptor(), "missing", resolution).error, ENOENT);
        EXPECT_EQ(open_below(jail.descriptor(), "top/file", resolution).error, ENOTDIR);
    }
}

TEST(OpenBeneath, ALinkAnywhereOnThePathIsRefusedEvenOneThatStaysInside) {
    const Jail jail;
    fs::create_symlink(jail / "outside", jail / "jail/out");
    fs::create_symlink(jail / "outside/file", jail / "jail/secret");
    fs::create_symlink("sub", jail / "jail/alias");
    fs::create_symlink("top", jail / "jail/top-link");
    for (const BeneathResolution resolution : kBoth) {
        SCOPED_TRACE(name_of(resolution));
        for (const char* linked : {"out/file", "secret", "alias/file", "top-link"}) {
            const Opened opened = open_below(jail.descriptor(), linked, resolution);
            EXPECT_EQ(opened.inode, 0U) << linked;
            EXPECT_TRUE(opened.error == ELOOP || opened.error == EXDEV) << linked << ": " << opened.error;
        }
    }
}

TEST(OpenBeneath, ADirectorySwappedForALinkToOutsideIsNeverFollowed) {
    const Jail jail;
    fs::create_symlink(jail / "outside", jail / "jail/swap");
    const ino_t outside = inode_of(jail / "outside/file"), file = inode_of(jail / "jail/sub/file");
    for (const BeneathResolution resolution : kBoth) {
        SCOPED_TRACE(name_of(resolution));
        std::atomic<bool> done = false;
        std::atomic<int> swaps = 0, swap_error = 0;
        const std::string sub = (jail / "jail/sub").string(), swap = (jail / "jail/swap").string();
        // jail/sub and jail/swap change places without pause: a directory, then a link to outside.
        std::thread swapper([&] {
            while (!done) {
                if (::renameat2(AT_FDCWD, sub.c_str(), AT_FDCWD, swap.c_str(), RENAME_EXCHANGE) == 0) {
                    ++swaps;
                } else {
                    swap_error = errno;
                    return;
                }
                std::this_thread::yield();
            }
        });
        // The opens begin once the swapping has: on a busy machine the thread starts late.
        while (swaps == 0 && swap_error == 0) std::this_thread::yield();
        if (swap_error != 0) {
            swapper.join();
            FAIL() << "renameat2 cannot swap here: " << std::strerror(swap_error);
        }
        int escaped = 0;
        for (int attempt = 0; attempt < 2000; ++attempt) {
            if (open_below(jail.descriptor(), "sub/file", resolution).inode == outside) ++escaped;
        }
        done = true;
        swapper.join();
        EXPECT_EQ(escaped, 0) << "of 2000 opens, " << escaped << " reached the file outside";
        EXPECT_GT(swaps.load(), 0);
        if (fs::is_symlink(jail / "jail/sub"))
            ::renameat2(AT_FDCWD, sub.c_str(), AT_FDCWD, swap.c_str(), RENAME_EXCHANGE);
        EXPECT_EQ(open_below(jail.descriptor(), "sub/file", resolution).inode, file)
            << "the file inside is still reached";
    }
}
