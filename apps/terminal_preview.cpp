#include "terminal_preview.hpp"

#include <raster/io/held_signals.hpp>
#include <raster/io/kitty_graphics.hpp>
#include <raster/io/png.hpp>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

namespace {

// Closes the controlling terminal opened to read its answer.
class Descriptor {
public:
    explicit Descriptor(int fd) : fd_(fd) {}
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    [[nodiscard]] int get() const { return fd_; }

private:
    int fd_;
};

// Ctrl-C, Ctrl-Z and hang-ups wait while the terminal is raw, on whichever thread they land,
// and are raised again once it is restored (RawMode is destroyed first).
constexpr std::array<int, 5> kTerminalSignals{SIGINT, SIGQUIT, SIGTERM, SIGHUP, SIGTSTP};

// Raw input (no line editing, no echo) for the answer, and the terminal's own settings back after.
class RawMode {
public:
    explicit RawMode(int fd) : fd_(fd) {
        if (::tcgetattr(fd_, &before_) != 0) return;
        termios raw = before_;
        raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);
        raw.c_cc[VMIN] = 0;
        raw.c_cc[VTIME] = 0;
        active_ = ::tcsetattr(fd_, TCSANOW, &raw) == 0;
    }
    ~RawMode() {
        if (active_) ::tcsetattr(fd_, TCSANOW, &before_);
    }
    RawMode(const RawMode&) = delete;
    RawMode& operator=(const RawMode&) = delete;
    [[nodiscard]] bool active() const { return active_; }

private:
    int fd_;
    termios before_{};
    bool active_ = false;
};

bool write_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ::ssize_t written = ::write(fd, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        bytes.remove_prefix(static_cast<std::size_t>(written));
    }
    return true;
}

// Asks the terminal on standard output, reading its answer from the controlling terminal.
raster::KittyAnswer ask_terminal(int tty, std::chrono::milliseconds timeout) {
    // Our process id keeps the query's id apart from another program's on the same terminal.
    const std::uint32_t id = 0x52000000U | (static_cast<std::uint32_t>(::getpid()) & 0xFFFFFFU);
    const raster::HeldSignals held(kTerminalSignals);
    const RawMode raw(tty);
    if (!raw.active() || !write_all(1, raster::kitty_query(id))) return raster::KittyAnswer::incomplete;
    std::string answer;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0 || held.arrived()) return raster::KittyAnswer::incomplete;
        pollfd wait{tty, POLLIN, 0};
        const int ready = ::poll(&wait, 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0 || (wait.revents & POLLIN) == 0) return raster::KittyAnswer::incomplete;
        char buffer[256];
        const ::ssize_t got = ::read(tty, buffer, sizeof buffer);
        if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (got <= 0) return raster::KittyAnswer::incomplete;
        answer.append(buffer, static_cast<std::size_t>(got));
        if (const raster::KittyAnswer read = raster::read_kitty_answer(answer, id);
            read != raster::KittyAnswer::incomplete)
            return read;
    }
}

}  // namespace

std::string show_on_terminal(const raster::Framebuffer& image, std::span<const std::uint8_t> alpha,
                             std::chrono::milliseconds timeout) {
    if (::isatty(1) != 1) return "standard output is not a terminal";
    const Descriptor tty(::open("/dev/tty", O_RDWR | O_NOCTTY | O_CLOEXEC));
    if (tty.get() < 0) return "no controlling terminal to ask whether it shows pictures";
    // A job in the background that touched the terminal's settings would be stopped.
    if (::tcgetpgrp(tty.get()) != ::getpgrp()) return "running in the background, where the terminal cannot be asked";
    std::cout << std::flush;
    switch (ask_terminal(tty.get(), timeout)) {
    case raster::KittyAnswer::supported: break;
    case raster::KittyAnswer::unsupported:
        return "the terminal does not show Kitty graphics (Kitty, WezTerm, Ghostty and Konsole do)";
    case raster::KittyAnswer::refused: return "the terminal refused the Kitty graphics query";
    case raster::KittyAnswer::incomplete:
        return "the terminal did not answer the Kitty graphics query within " + std::to_string(timeout.count()) + " ms";
    }
    raster::TerminalWindow window;
    if (winsize size{}; ::ioctl(1, TIOCGWINSZ, &size) == 0)
        window = {size.ws_col, size.ws_row, size.ws_xpixel, size.ws_ypixel};
    const std::vector<std::uint8_t> png = raster::encode_png(image, alpha);
    // The cursor ends beside the picture's last row; the newline brings it under the picture.
    if (!write_all(1,
                   raster::kitty_display(png, raster::display_cells(image.width(), image.height(), window)) + "\n")) {
        return std::string("cannot write to the terminal: ") + std::strerror(errno);
    }
    return "";
}
