#include "file_events.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace test_support {
namespace {

// One inotify descriptor watching `path`, closed whatever happens.
class Watch {
public:
    Watch(const std::filesystem::path& path, std::uint32_t mask, int flags)
        : descriptor_(::inotify_init1(flags | IN_CLOEXEC)) {
        if (descriptor_ < 0) throw std::runtime_error(std::string("inotify_init1: ") + std::strerror(errno));
        if (::inotify_add_watch(descriptor_, path.c_str(), mask) < 0) {
            const int error = errno;
            ::close(descriptor_);
            throw std::runtime_error("inotify_add_watch " + path.string() + ": " + std::strerror(error));
        }
    }
    ~Watch() {
        if (descriptor_ >= 0) ::close(descriptor_);
    }
    Watch(const Watch&) = delete;
    Watch& operator=(const Watch&) = delete;
    [[nodiscard]] int descriptor() const { return descriptor_; }
    [[nodiscard]] int release() { return std::exchange(descriptor_, -1); }

private:
    int descriptor_;
};

// Takes whole events off the front of `bytes` while `take` wants them (returns true).
template <typename Take>
void take_events(std::string& bytes, Take take) {
    std::size_t at = 0;
    while (bytes.size() - at >= sizeof(inotify_event)) {
        inotify_event header{};
        std::memcpy(&header, bytes.data() + at, sizeof header);
        const std::size_t whole = sizeof header + header.len;
        if (bytes.size() - at < whole) break;
        const bool wanted =
            take(header, std::string(bytes.c_str() + at + sizeof header));  // the name is padded with NULs
        if (!wanted) break;
        at += whole;
    }
    bytes.erase(0, at);
}

}  // namespace

int file_events_during(const std::filesystem::path& path, std::uint32_t mask, const std::function<void()>& action) {
    const Watch watch(path, mask, IN_NONBLOCK);
    action();
    int count = 0;
    std::string bytes;
    char buffer[4096];
    for (::ssize_t got; (got = ::read(watch.descriptor(), buffer, sizeof buffer)) > 0;)
        bytes.append(buffer, static_cast<std::size_t>(got));
    take_events(bytes, [&](const inotify_event& event, const std::string&) {
        count += (event.mask & mask) != 0 ? 1 : 0;
        return true;
    });
    return count;
}

DirectoryEvents::DirectoryEvents(const std::filesystem::path& directory)
    : descriptor_(Watch(directory, IN_CREATE | IN_DELETE | IN_MOVED_FROM, 0).release()) {
}  // a temporary file leaves by rename

DirectoryEvents::~DirectoryEvents() { ::close(descriptor_); }

bool DirectoryEvents::next(pid_t pid, Event& event) {
    // By number: Debian 12's <sys/pidfd.h> declares pidfd_open without extern "C".
    const int process = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
    if (process < 0) throw std::runtime_error(std::string("pidfd_open: ") + std::strerror(errno));
    bool found = false, ended = false;
    for (;;) {
        take_events(pending_, [&](const inotify_event& raw, const std::string& name) {
            if (found) return false;
            if ((raw.mask & (IN_CREATE | IN_DELETE | IN_MOVED_FROM)) == 0) return true;  // IN_IGNORED and such
            event = {(raw.mask & IN_CREATE) != 0, name};
            found = true;
            return true;
        });
        if (found || ended) break;
        pollfd waits[2] = {{descriptor_, POLLIN, 0}, {process, POLLIN, 0}};
        if (::poll(waits, 2, -1) < 0) {
            if (errno == EINTR) continue;
            ::close(process);
            throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
        }
        ended = waits[1].revents != 0;
        // Looked at again after the end was seen: every event the process caused is queued by then.
        pollfd queued{descriptor_, POLLIN, 0};
        if (::poll(&queued, 1, 0) > 0 && (queued.revents & POLLIN) != 0) {
            char buffer[4096];
            const ::ssize_t got = ::read(descriptor_, buffer, sizeof buffer);
            if (got > 0) pending_.append(buffer, static_cast<std::size_t>(got));
        }
    }
    ::close(process);
    return found;
}

}  // namespace test_support
