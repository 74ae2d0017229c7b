// The reader's child end to end: limits, the trip back, the parent's checks; stays whole so they read together.
#include "io/reader_process.hpp"

#include "io/model_wire.hpp"
#include "io/shared_bytes.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <new>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>
#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define RASTER_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RASTER_ADDRESS_SANITIZER 1
#endif
#endif

namespace raster {

std::uint64_t default_max_memory() noexcept {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return std::uint64_t{1} << 30;
    return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 2;
}

namespace detail {
namespace {

// What the child sends first: a model (in the shared memory, or in the message where there is
// none), a reason it could not read one, or that memory ran out.
enum class Outcome : std::uint8_t { model = 'M', model_in_message = 'P', refused = 'E', out_of_memory = 'N' };

// Set by the child's new-handler: assimp turns a failed allocation into "could not read", so
// the child remembers that memory ran out. Static because a new-handler reaches nothing else.
volatile std::sig_atomic_t memory_ran_out = 0;

void note_memory_ran_out() {
    memory_ran_out = 1;
    std::set_new_handler(nullptr);
    throw std::bad_alloc();
}

std::string memory_text(std::uint64_t bytes) {
    char text[32];
    const bool gib = bytes >= (std::uint64_t{1} << 30);
    std::snprintf(text, sizeof text, gib ? "%.1f GiB" : "%.0f MiB",
                  static_cast<double>(bytes) / static_cast<double>(std::uint64_t{1} << (gib ? 30 : 20)));
    return text;
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", seconds);
    return text;
}

// The address space the process holds now, from /proc/self/statm; 0 where it cannot be read.
std::uint64_t address_space_now() {
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    if (statm == nullptr) return 0;
    unsigned long long pages = 0;
    const int got = std::fscanf(statm, "%llu", &pages);
    std::fclose(statm);
    return got == 1 ? pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGE_SIZE)) : 0;
}

void write_all(int descriptor, const std::vector<std::uint8_t>& bytes) {
    std::size_t sent = 0;
    while (sent < bytes.size()) {
        const ::ssize_t n = ::write(descriptor, bytes.data() + sent, bytes.size() - sent);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) ::_exit(3);
        sent += static_cast<std::size_t>(n);
    }
}

[[noreturn]] void run_child(const std::function<Model()>& read, int out, const SharedBytes& shared,
                            std::uint64_t max_memory, double max_seconds) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlives the process waiting for it
    const rlimit no_core{0, 0}, no_files{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    ::setrlimit(RLIMIT_FSIZE, &no_files);  // a reader writes nothing but the pipe
    const auto cpu = static_cast<rlim_t>(std::ceil(max_seconds));
    const rlimit processor{cpu, cpu + 1};
    ::setrlimit(RLIMIT_CPU, &processor);
    // A reader's threads share one heap: each arena of its own would reserve 64 MiB of the address space capped here.
    ::mallopt(M_ARENA_MAX, 1);
    const rlim_t ceiling = address_space_now() + max_memory;
#ifndef RASTER_ADDRESS_SANITIZER  // its shadow memory takes terabytes of address space
    const rlimit memory{ceiling, ceiling};
    ::setrlimit(RLIMIT_AS, &memory);
#else
    (void)ceiling;
#endif
    std::signal(SIGPIPE, SIG_DFL);
    std::set_new_handler(note_memory_ran_out);
    std::vector<std::uint8_t> message(sizeof(std::uint64_t));  // its length goes first
    try {
        Model model = read();
        // The model goes into the shared memory, within this process's address space as a message would.
        const std::size_t size = model_wire_bytes(model);
        if (size > max_memory) throw std::bad_alloc();
        if (shared.descriptor() < 0) {  // no shared memory: the model follows in the message
            message.push_back(static_cast<std::uint8_t>(Outcome::model_in_message));
            message.resize(message.size() + size);
            WireWriter wire(std::span<std::uint8_t>(message).last(size));
            write_model_wire(model, wire);
        } else {
            const SharedMapping into = SharedMapping::for_writing(shared, size);
            WireWriter wire(into.bytes());
            write_model_wire(model, wire);
            message.push_back(static_cast<std::uint8_t>(Outcome::model));
            WireWriter(message).value(static_cast<std::uint64_t>(size));
        }
    } catch (const std::bad_alloc&) {
        message.assign(sizeof(std::uint64_t) + 1, static_cast<std::uint8_t>(Outcome::out_of_memory));
    } catch (const std::exception& problem) {
        const std::string why = problem.what();
        message.assign(sizeof(std::uint64_t) + 1,
                       static_cast<std::uint8_t>(memory_ran_out != 0 ? Outcome::out_of_memory : Outcome::refused));
        message.insert(message.end(), why.begin(), why.end());
    }
    const std::uint64_t length = message.size() - sizeof length;
    std::memcpy(message.data(), &length, sizeof length);
    write_all(out, message);
    ::_exit(0);
}

// The limits as they apply: the default memory where none is set, and never no time at all.
std::pair<std::uint64_t, double> limits_in_force(const ReaderLimits& limits) {
    return {limits.max_memory > 0 ? limits.max_memory : default_max_memory(), std::max(limits.max_seconds, 0.001)};
}

std::string signal_name(int signal) {
    switch (signal) {
    case SIGSEGV: return "segmentation fault";
    case SIGBUS: return "bus error";
    case SIGABRT: return "aborted";
    case SIGILL: return "illegal instruction";
    case SIGFPE: return "arithmetic exception";
    default: return "signal " + std::to_string(signal);
    }
}

}  // namespace

ChildOutcome run_reader_child(const std::function<Model()>& read, const ReaderLimits& limits, ModelPassage passage) {
    const auto [max_memory, max_seconds] = limits_in_force(limits);
    ChildOutcome outcome;
    try {
        // What is not written takes no memory.
        if (passage == ModelPassage::shared_memory) outcome.shared = SharedBytes::create(max_memory);
    } catch (const std::runtime_error&) {
        // Refused (no memfd_create, a sandbox's EPERM, no descriptors left): the pipe carries the model.
    }
    int pipe_ends[2];
    if (::pipe2(pipe_ends, O_CLOEXEC) != 0) {
        outcome.start_error = std::strerror(errno);
        return outcome;
    }
    const ::pid_t child = ::fork();
    if (child < 0) {
        outcome.start_error = std::strerror(errno);
        ::close(pipe_ends[0]);
        ::close(pipe_ends[1]);
        return outcome;
    }
    if (child == 0) {
        ::close(pipe_ends[0]);
        run_child(read, pipe_ends[1], outcome.shared, max_memory, max_seconds);
    }
    ::close(pipe_ends[1]);
    // The length comes first, so the message lands in one buffer of its own size.
    std::vector<std::uint8_t>& received = outcome.message;
    received.resize(sizeof(std::uint64_t));
    std::size_t got = 0;
    bool length_known = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(max_seconds);
    while (got < received.size()) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            outcome.timed_out = true;
            break;
        }
        pollfd ready{pipe_ends[0], POLLIN, 0};
        const int polled = ::poll(&ready, 1, static_cast<int>(std::min<long long>(left, 1000)));
        if (polled < 0 && errno != EINTR) break;
        if (polled <= 0) continue;
        const ::ssize_t n = ::read(pipe_ends[0], received.data() + got, received.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += static_cast<std::size_t>(n);
        if (!length_known && got == received.size()) {
            std::uint64_t length = 0;
            std::memcpy(&length, received.data(), sizeof length);
            if (length > max_memory) {
                outcome.too_large = true;
                break;
            }
            received.assign(static_cast<std::size_t>(length), 0);
            got = 0;
            length_known = true;
        }
    }
    if (!length_known || got < received.size()) received.clear();  // the child died before it had said all
    ::close(pipe_ends[0]);
    if (outcome.timed_out || outcome.too_large) ::kill(child, SIGKILL);
    rusage used{};
    while (::wait4(child, &outcome.status, 0, &used) < 0 && errno == EINTR) {
    }
    outcome.processor_seconds = static_cast<double>(used.ru_utime.tv_sec + used.ru_stime.tv_sec) +
                                1e-6 * static_cast<double>(used.ru_utime.tv_usec + used.ru_stime.tv_usec);
    return outcome;
}

std::uint64_t memory_in_force(const ReaderLimits& limits) { return limits_in_force(limits).first; }

std::string memory_refusal(const std::string& name, const std::string& reader, const ReaderLimits& limits) {
    return name + ": the " + reader + " reader needed more than " + memory_text(memory_in_force(limits)) +
           " of memory; raise --max-memory to allow it";
}

Model model_from_outcome(const ChildOutcome& outcome, const std::string& name, const std::string& reader,
                         const ReaderLimits& limits) {
    const auto [max_memory, max_seconds] = limits_in_force(limits);
    const std::string memory_refusal = detail::memory_refusal(name, reader, limits);
    const std::string time_refusal = name + ": the " + reader + " reader took more than " + seconds_text(max_seconds) +
                                     "; raise --max-seconds to allow it";
    if (!outcome.start_error.empty())
        throw std::runtime_error(name + ": cannot start the reader process: " + outcome.start_error);
    if (outcome.timed_out) throw std::runtime_error(time_refusal);
    if (outcome.too_large) throw std::runtime_error(memory_refusal);
    const std::vector<std::uint8_t>& received = outcome.message;
    const int status = outcome.status;
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        if (signal == SIGXCPU || (signal == SIGKILL && outcome.processor_seconds >= std::ceil(max_seconds)))
            throw std::runtime_error(time_refusal);
        if (signal == SIGKILL)
            throw std::runtime_error(name + ": the " + reader +
                                     " reader was killed (by the system, perhaps for want of memory)");
        throw std::runtime_error(name + ": the " + reader + " reader crashed (" + signal_name(signal) + ")");
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || received.empty()) {
        // A sanitizer's report ends the child with an exit code of its own.
        throw std::runtime_error(name + ": the " + reader + " reader crashed (exit status " +
                                 std::to_string(WEXITSTATUS(status)) + ")");
    }
    const auto kind = static_cast<Outcome>(received.front());
    const std::span<const std::uint8_t> rest = std::span<const std::uint8_t>(received).subspan(1);
    if (kind == Outcome::out_of_memory) throw std::runtime_error(memory_refusal);
    if (kind == Outcome::refused) throw std::runtime_error(std::string(rest.begin(), rest.end()));
    if (kind != Outcome::model && kind != Outcome::model_in_message)
        throw std::runtime_error(name + ": the " + reader + " reader sent nothing raster understands");
    try {
        // Its length within --max-memory was checked as it arrived.
        if (kind == Outcome::model_in_message) return model_from_wire(rest);
        // The message says how many bytes of the shared memory hold the model.
        if (rest.size() != sizeof(std::uint64_t)) WireReader::broken();
        const auto size = WireReader(rest).value<std::uint64_t>();
        if (size > max_memory) throw std::runtime_error(memory_refusal);
        const SharedMapping model = SharedMapping::for_reading(outcome.shared, static_cast<std::size_t>(size));
        return model_from_wire(model.bytes());
    } catch (const std::runtime_error& problem) {
        if (problem.what() == memory_refusal) throw;
        throw std::runtime_error(name + ": " + problem.what());
    }
}

Model read_in_child(const std::function<Model()>& read, const std::string& name, const std::string& reader,
                    const ReaderLimits& limits, double* processor_seconds) {
    if (!limits.separate_process) return read();
    const ChildOutcome outcome = run_reader_child(read, limits);
    if (processor_seconds != nullptr) *processor_seconds = outcome.processor_seconds;
    return model_from_outcome(outcome, name, reader, limits);
}

}  // namespace detail
}  // namespace raster
