#pragma once

#include <array>
#include <csignal>
#include <span>
#include <vector>

// Signals that wait while something must not be cut short (an output half written, a terminal
// left raw), on whichever thread of the process they land.
namespace raster {

// The signals that end a program from outside and leave it no say: what an output write holds.
inline constexpr std::array<int, 3> kInterruptSignals{SIGINT, SIGTERM, SIGHUP};

// Holds the given signals process-wide for its lifetime: a handler that only notes the signal
// replaces theirs while any HeldSignals holds them. When the last holder of a signal is gone,
// the handler from before is back and a signal that came meanwhile is raised again. Holders on
// several threads, and nested holders on one, share the one handler. Once a held signal has
// come, a new holder on another thread waits until it has been raised, so a stream of writes
// cannot hold it off for ever. Signals that were ignored stay ignored.
class HeldSignals {
public:
    explicit HeldSignals(std::span<const int> signals = kInterruptSignals);
    ~HeldSignals();
    HeldSignals(const HeldSignals&) = delete;
    HeldSignals& operator=(const HeldSignals&) = delete;

    // Whether one of the held signals has come and waits to be raised.
    [[nodiscard]] bool arrived() const;

private:
    std::vector<int> signals_;
};

}  // namespace raster
