// Signals held process-wide while something must not be cut short, and raised again after.
#include <raster/io/held_signals.hpp>

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <csignal>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>
#include <unistd.h>

namespace {

// How often SIGUSR1's own handler ran; static because a handler reaches nothing else.
volatile std::sig_atomic_t handled = 0;
extern "C" void count_signal(int) { handled = handled + 1; }

constexpr std::array<int, 1> kUser1{SIGUSR1};

// Gives SIGUSR1 a handler that counts, for one test.
class CountingHandler {
public:
    CountingHandler() {
        handled = 0;
        struct sigaction count {};
        count.sa_handler = count_signal;
        sigemptyset(&count.sa_mask);
        ::sigaction(SIGUSR1, &count, &before_);
    }
    ~CountingHandler() { ::sigaction(SIGUSR1, &before_, nullptr); }
    CountingHandler(const CountingHandler&) = delete;
    CountingHandler& operator=(const CountingHandler&) = delete;

private:
    struct sigaction before_ {};
};

void (*current_handler(int signal))(int) {
    struct sigaction now {};
    ::sigaction(signal, nullptr, &now);
    return now.sa_handler;
}

// The state /proc gives a thread of this process: 'S' while it sleeps in a wait, '\0' once it is gone.
char thread_state(pid_t thread) {
    std::ifstream stat("/proc/self/task/" + std::to_string(thread) + "/stat");
    const std::string text{std::istreambuf_iterator<char>(stat), std::istreambuf_iterator<char>()};
    const std::size_t name_end = text.rfind(')');  // the thread's name may hold spaces and brackets
    return name_end == std::string::npos || name_end + 2 >= text.size() ? '\0' : text[name_end + 2];
}

}  // namespace

TEST(HeldSignals, ASignalThatCameWhileHeldIsRaisedOnceWhenTheLastHolderOnAnyThreadIsGone) {
    const CountingHandler counting;
    std::optional<raster::HeldSignals> outer(std::in_place, kUser1);
    std::optional<raster::HeldSignals> nested(std::in_place, kUser1);
    std::thread([] {
        const raster::HeldSignals other(kUser1);
        ::raise(SIGUSR1);
        ::raise(SIGUSR1);
    }).join();
    EXPECT_EQ(handled, 0);
    EXPECT_TRUE(outer->arrived());
    nested.reset();
    EXPECT_EQ(handled, 0) << "the outer holder still holds it";
    outer.reset();
    EXPECT_EQ(handled, 1);
    EXPECT_EQ(current_handler(SIGUSR1), &count_signal) << "the handler from before is back";
    ::raise(SIGUSR1);
    EXPECT_EQ(handled, 2);
}

TEST(HeldSignals, AHolderOnAnotherThreadWaitsUntilASignalThatCameHasBeenRaised) {
    const CountingHandler counting;
    std::optional<raster::HeldSignals> first(std::in_place, kUser1);
    ::raise(SIGUSR1);
    std::atomic<pid_t> second_thread = 0;
    std::atomic<bool> started = false;
    std::thread second([&] {
        second_thread = ::gettid();
        const raster::HeldSignals next(kUser1);
        started = true;
    });
    while (second_thread == 0) std::this_thread::yield();
    // Asleep before it holds: the one wait on its way there is the holder's own.
    while (!started && thread_state(second_thread) != 'S') std::this_thread::yield();
    EXPECT_FALSE(started) << "a new holder would put the signal off";
    first.reset();
    second.join();
    EXPECT_TRUE(started);
    EXPECT_EQ(handled, 1);
}

TEST(HeldSignals, AnIgnoredSignalStaysIgnored) {
    struct sigaction ignore {
    }, before{};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGUSR2, &ignore, &before);
    {
        const std::array<int, 1> user2{SIGUSR2};
        const raster::HeldSignals held(user2);
        EXPECT_EQ(current_handler(SIGUSR2), SIG_IGN);
        ::raise(SIGUSR2);
        EXPECT_FALSE(held.arrived());
    }
    EXPECT_EQ(current_handler(SIGUSR2), SIG_IGN);
    ::sigaction(SIGUSR2, &before, nullptr);
}
