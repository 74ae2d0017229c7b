#include "io/open_beneath.hpp"

#include <cerrno>
#include <string>
#include <vector>
#include <fcntl.h>
#include <linux/openat2.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace raster::detail {
namespace {

int fail(int error) {
    errno = error;
    return -1;
}

// The path's components with `.` and `..` resolved by name; empty with `escapes` set when `..`
// would climb above the start, or when the path is absolute.
std::vector<std::string> components_of(const std::filesystem::path& relative, bool& escapes) {
    escapes = relative.is_absolute();
    std::vector<std::string> names;
    for (const std::filesystem::path& part : relative) {
        const std::string name = part.string();
        if (name.empty() || name == ".") continue;
        if (name != "..") {
            names.push_back(name);
        } else if (names.empty()) {
            escapes = true;
        } else {
            names.pop_back();
        }
    }
    if (escapes) names.clear();
    return names;
}

int walk_beneath(int directory, const std::vector<std::string>& names) {
    if (names.empty()) return ::openat(directory, ".", O_PATH | O_CLOEXEC);
    int current = ::fcntl(directory, F_DUPFD_CLOEXEC, 0);
    for (std::size_t k = 0; current >= 0 && k < names.size(); ++k) {
        // O_NOFOLLOW with O_PATH opens a link itself, whose kind the descriptor then shows.
        const int next = ::openat(current, names[k].c_str(), O_PATH | O_NOFOLLOW | O_CLOEXEC);
        const int opened_errno = errno;
        ::close(current);
        if (next < 0) return fail(opened_errno);
        struct stat status {};
        int error = 0;
        if (::fstat(next, &status) != 0) {
            error = errno;
        } else if (S_ISLNK(status.st_mode)) {
            error = ELOOP;
        } else if (k + 1 < names.size() && !S_ISDIR(status.st_mode)) {
            error = ENOTDIR;
        }
        if (error != 0) {
            ::close(next);
            return fail(error);
        }
        current = next;
    }
    return current;
}

}  // namespace

int open_beneath(int directory, const std::filesystem::path& relative, BeneathResolution resolution) {
    bool escapes = false;
    const std::vector<std::string> names = components_of(relative, escapes);
    if (escapes) return fail(EXDEV);
    if (resolution == BeneathResolution::kernel_first) {
        std::string joined = ".";
        for (const std::string& name : names) joined += "/" + name;
        open_how how{};
        how.flags = static_cast<std::uint64_t>(O_PATH | O_CLOEXEC);
        how.resolve = RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS | RESOLVE_NO_MAGICLINKS;
        const long descriptor = ::syscall(SYS_openat2, directory, joined.c_str(), &how, sizeof how);
        if (descriptor >= 0 || (errno != ENOSYS && errno != EPERM)) return static_cast<int>(descriptor);
    }
    return walk_beneath(directory, names);
}

}  // namespace raster::detail
