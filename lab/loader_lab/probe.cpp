#include "loader_lab/probe.hpp"

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <system_error>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace loader_lab {
namespace {

// A reading as one line of text, for the pipe from the child.
std::string encode(const Reading& r) {
    std::ostringstream out;
    out.precision(17);
    out << r.triangles << ' ' << r.flat << ' ' << r.vertices << ' ' << r.materials << ' ' << r.textures;
    for (const glm::dvec3& p : {r.box.low, r.box.high}) out << ' ' << p.x << ' ' << p.y << ' ' << p.z;
    out << ' ' << one_line(r.note, 400);
    return out.str();
}

Reading decode(const std::string& text) {
    // strtod, not operator>>: the box of a file with infinite vertices is written as inf.
    Reading r;
    const char* at = text.c_str();
    char* end = nullptr;
    const auto next = [&] {
        const double v = std::strtod(at, &end);
        at = end;
        return v;
    };
    r.triangles = static_cast<std::size_t>(next());
    r.flat = static_cast<std::size_t>(next());
    r.vertices = static_cast<std::size_t>(next());
    r.materials = static_cast<std::size_t>(next());
    r.textures = static_cast<std::size_t>(next());
    r.box.low = {next(), next(), next()};
    r.box.high = {next(), next(), next()};
    while (*at == ' ') ++at;
    r.note = at;
    return r;
}

void write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

Outcome probe(Loader loader, const fs::path& path) {
    std::array<int, 2> channel{};
    if (pipe(channel.data()) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
    std::cout.flush();
    std::cerr.flush();
    const pid_t child = fork();
    if (child < 0) throw std::system_error(errno, std::generic_category(), "fork");
    if (child == 0) {
        close(channel[0]);
        std::string line;
        try {
            line = "accepted " + encode(read_with(loader, path));
        } catch (const WalkError& problem) {
            line = "unsafe " + one_line(problem.what(), 400);
        } catch (const std::exception& problem) {
            line = "refused " + one_line(problem.what(), 400);
        }
        write_all(channel[1], line);
        _exit(0);  // no destructors or stdio flushes of the parent's state
    }
    close(channel[1]);
    std::string text;
    bool hung = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kProbeSeconds);
    for (;;) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            hung = true;
            break;
        }
        pollfd ready{channel[0], POLLIN, 0};
        const int events = poll(&ready, 1, static_cast<int>(left));
        if (events <= 0) continue;  // interrupted or timed out: the deadline decides
        std::array<char, 4096> buffer{};
        const ssize_t got = read(channel[0], buffer.data(), buffer.size());
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;  // the child finished, or died
        text.append(buffer.data(), static_cast<std::size_t>(got));
    }
    close(channel[0]);
    if (hung) kill(child, SIGKILL);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    Outcome outcome;
    if (hung) {
        outcome.status = "hung (killed after " + std::to_string(kProbeSeconds) + " s)";
    } else if (WIFSIGNALED(status)) {
        const char* signal_name = sigabbrev_np(WTERMSIG(status));
        outcome.status = std::string("crashed (SIG") +
                         (signal_name != nullptr ? signal_name : std::to_string(WTERMSIG(status)).c_str()) + ")";
    } else if (text.rfind("accepted ", 0) == 0) {
        outcome.status = "accepted";
        outcome.reading = decode(text.substr(9));
        outcome.message = outcome.reading.note;
    } else if (text.rfind("refused ", 0) == 0) {
        outcome.status = "refused";
        outcome.message = text.substr(8);
    } else if (text.rfind("unsafe ", 0) == 0) {
        outcome.status = "loaded, unsafe";
        outcome.message = "our walk: " + text.substr(7);
    } else {
        outcome.status = "died (exit " + std::to_string(WEXITSTATUS(status)) + ")";
    }
    return outcome;
}

}  // namespace loader_lab
