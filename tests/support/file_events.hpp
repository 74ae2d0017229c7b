#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <sys/types.h>

namespace test_support {

// How many inotify events of `mask` (IN_ACCESS: a read; IN_OPEN: an open) `path` saw while
// `action` ran, in this process or any other: proof of what was done to a file, not a clock.
int file_events_during(const std::filesystem::path& path, std::uint32_t mask, const std::function<void()>& action);

// The files created in and removed from one directory, in order, as inotify reports them.
class DirectoryEvents {
public:
    struct Event {
        bool created = false;  // created, or else deleted or renamed away
        std::string name;
    };

    explicit DirectoryEvents(const std::filesystem::path& directory);
    ~DirectoryEvents();
    DirectoryEvents(const DirectoryEvents&) = delete;
    DirectoryEvents& operator=(const DirectoryEvents&) = delete;

    // Waits for the next event; false once process `pid`, a child of this one, has ended first.
    bool next(pid_t pid, Event& event);

private:
    int descriptor_;
    std::string pending_;  // read but not yet returned
};

}  // namespace test_support
