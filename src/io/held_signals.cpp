#include <raster/io/held_signals.hpp>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>

namespace raster {
namespace {

// Which held signals came, by number; static because a handler reaches nothing else, atomic
// because the handler may run on another thread than the holder's.
std::atomic<bool> arrived_signals[NSIG] = {};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void note_signal(int signal) { arrived_signals[signal] = true; }

// How many holders each signal has and the handler it had before: as process-wide as the
// handlers themselves, so shared by every holder on every thread.
struct Holders {
    std::mutex mutex;
    std::condition_variable released;
    std::array<int, NSIG> count{};
    std::array<struct sigaction, NSIG> before{};
};

Holders& holders() {
    static Holders shared;
    return shared;
}

// The holders on this thread: a nested holder never waits for the one around it.
thread_local int held_on_this_thread = 0;

bool ignored(const struct sigaction& action) {
    return (action.sa_flags & SA_SIGINFO) == 0 && action.sa_handler == SIG_IGN;
}

}  // namespace

HeldSignals::HeldSignals(std::span<const int> signals) : signals_(signals.begin(), signals.end()) {
    for (const int signal : signals_) {
        if (signal <= 0 || signal >= NSIG)
            throw std::invalid_argument("there is no signal " + std::to_string(signal) + " to hold");
    }
    Holders& shared = holders();
    std::unique_lock lock(shared.mutex);
    // Once a held signal came, writes that start meanwhile must not put it off without end.
    if (held_on_this_thread == 0) {
        shared.released.wait(lock, [&] {
            for (const int signal : signals_) {
                if (shared.count[static_cast<std::size_t>(signal)] > 0 && arrived_signals[signal]) return false;
            }
            return true;
        });
    }
    for (const int signal : signals_) {
        if (shared.count[static_cast<std::size_t>(signal)]++ > 0) continue;
        ::sigaction(signal, nullptr, &shared.before[static_cast<std::size_t>(signal)]);
        if (ignored(shared.before[static_cast<std::size_t>(signal)])) continue;  // nohup's SIGHUP stays ignored
        struct sigaction note {};
        note.sa_handler = note_signal;
        note.sa_flags = SA_RESTART;  // the other threads' reads and writes go on undisturbed
        sigemptyset(&note.sa_mask);
        ::sigaction(signal, &note, nullptr);
    }
    ++held_on_this_thread;
}

HeldSignals::~HeldSignals() {
    Holders& shared = holders();
    const std::lock_guard lock(shared.mutex);
    --held_on_this_thread;
    for (const int signal : signals_) {
        if (--shared.count[static_cast<std::size_t>(signal)] == 0)
            ::sigaction(signal, &shared.before[static_cast<std::size_t>(signal)], nullptr);
    }
    // Raised with the lock held: no new holder starts before the signal has done what it does.
    for (const int signal : signals_) {
        if (shared.count[static_cast<std::size_t>(signal)] == 0 && arrived_signals[signal]) {
            arrived_signals[signal] = false;
            ::raise(signal);
        }
    }
    shared.released.notify_all();
}

bool HeldSignals::arrived() const {
    for (const int signal : signals_) {
        if (arrived_signals[signal]) return true;
    }
    return false;
}

}  // namespace raster
