#include <raster/io/reader_service.hpp>

#include "io/model_reading.hpp"
#include "io/reader_process.hpp"

#include <raster/io/input_file.hpp>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <type_traits>
#include <unistd.h>
#include <vector>

namespace raster {
namespace {

// Bytes in one direction of the socket, each message its length first.
class Message {
public:
    template <typename T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* first = reinterpret_cast<const std::uint8_t*>(&value);
        bytes_.insert(bytes_.end(), first, first + sizeof value);
    }
    void put_text(const std::string& text) {
        put(static_cast<std::uint64_t>(text.size()));
        bytes_.insert(bytes_.end(), text.begin(), text.end());
    }
    void put_bytes(const std::vector<std::uint8_t>& bytes) {
        put(static_cast<std::uint64_t>(bytes.size()));
        bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
    }
    [[nodiscard]] const std::vector<std::uint8_t>& bytes() const noexcept { return bytes_; }

private:
    std::vector<std::uint8_t> bytes_;
};

// Reads a message back in the order it was put; throws std::runtime_error past its end.
class Reading {
public:
    explicit Reading(const std::vector<std::uint8_t>& bytes) : bytes_(bytes) {}
    template <typename T>
    T get() {
        T value;
        std::memcpy(&value, take(sizeof value), sizeof value);
        return value;
    }
    std::string get_text() {
        const auto size = get<std::uint64_t>();
        const auto* first = take(static_cast<std::size_t>(size));
        return {reinterpret_cast<const char*>(first), static_cast<std::size_t>(size)};
    }
    std::vector<std::uint8_t> get_bytes() {
        const auto size = get<std::uint64_t>();
        const auto* first = take(static_cast<std::size_t>(size));
        return {first, first + size};
    }

private:
    const std::uint8_t* take(std::size_t size) {
        if (size > bytes_.size() - at_) throw std::runtime_error("a message from the reader service was cut short");
        const std::uint8_t* first = bytes_.data() + at_;
        at_ += size;
        return first;
    }
    const std::vector<std::uint8_t>& bytes_;
    std::size_t at_ = 0;
};

bool send_all(int socket, const std::vector<std::uint8_t>& bytes) {
    const std::uint64_t length = bytes.size();
    std::vector<std::uint8_t> framed(sizeof length);
    std::memcpy(framed.data(), &length, sizeof length);
    framed.insert(framed.end(), bytes.begin(), bytes.end());
    for (std::size_t sent = 0; sent < framed.size();) {
        const ::ssize_t n = ::send(socket, framed.data() + sent, framed.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        sent += static_cast<std::size_t>(n);
    }
    return true;
}

// One whole message, or false at the end of the stream or after `timeout_ms` (-1: none).
bool receive(int socket, std::vector<std::uint8_t>& message, int timeout_ms) {
    std::uint64_t length = 0;
    std::size_t got = 0;
    const auto fill = [&](std::uint8_t* into, std::size_t size) {
        for (got = 0; got < size;) {
            pollfd ready{socket, POLLIN, 0};
            const int polled = ::poll(&ready, 1, timeout_ms);
            if (polled < 0 && errno == EINTR) continue;
            if (polled <= 0) return false;
            const ::ssize_t n = ::recv(socket, into + got, size - got, 0);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            got += static_cast<std::size_t>(n);
        }
        return true;
    };
    if (!fill(reinterpret_cast<std::uint8_t*>(&length), sizeof length)) return false;
    message.assign(static_cast<std::size_t>(length), 0);
    return fill(message.data(), message.size());
}

// The service: each request read, its reader forked, what the reader left sent back.
[[noreturn]] void serve(int socket) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    std::vector<std::uint8_t> request;
    while (receive(socket, request, -1)) {
        detail::ChildOutcome outcome;
        try {
            Reading in(request);
            const std::filesystem::path path = in.get_text();
            ObjOptions options;
            options.crease_degrees = in.get<double>();
            options.load_textures = in.get<std::uint8_t>() != 0;
            options.max_texels = in.get<std::size_t>();
            options.max_line_bytes = in.get<std::size_t>();
            options.confine = in.get_text();
            options.limits.max_memory = in.get<std::uint64_t>();
            options.limits.max_seconds = in.get<double>();
            outcome = detail::run_reader_child([&] { return detail::read_model_here(path, options); }, options.limits);
        } catch (const std::exception& problem) {
            outcome.start_error = problem.what();
        }
        Message out;
        out.put_bytes(outcome.message);
        out.put(outcome.status);
        out.put(outcome.processor_seconds);
        out.put(static_cast<std::uint8_t>(outcome.timed_out));
        out.put(static_cast<std::uint8_t>(outcome.too_large));
        out.put_text(outcome.start_error);
        if (!send_all(socket, out.bytes())) break;
    }
    ::_exit(0);
}

}  // namespace

ReaderService::ReaderService() {
    int ends[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
        throw std::runtime_error(std::string("cannot start the model reader service: ") + std::strerror(errno));
    }
    pid_ = ::fork();
    if (pid_ < 0) {
        const int error = errno;
        ::close(ends[0]);
        ::close(ends[1]);
        throw std::runtime_error(std::string("cannot start the model reader service: ") + std::strerror(error));
    }
    if (pid_ == 0) {
        ::close(ends[0]);
        serve(ends[1]);
    }
    ::close(ends[1]);
    socket_ = ends[0];
}

ReaderService::~ReaderService() {
    ::close(socket_);  // the service reads the end of its stream and leaves
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
}

Model ReaderService::read(const std::filesystem::path& path, const ObjOptions& options) const {
    const std::string name = printable(path.string());
    const std::string reader = detail::reader_name(path);
    Message request;
    request.put_text(path.string());
    request.put(options.crease_degrees);
    request.put(static_cast<std::uint8_t>(options.load_textures));
    request.put(options.max_texels);
    request.put(options.max_line_bytes);
    request.put_text(options.confine.string());
    request.put(options.limits.max_memory);
    request.put(options.limits.max_seconds);
    std::vector<std::uint8_t> answer;
    {
        const std::lock_guard<std::mutex> mine(turn_);
        // The service enforces the limits; a minute more here only guards against its own end.
        const int patience_ms = static_cast<int>(std::min(options.limits.max_seconds + 60.0, 2.0e9 / 1000.0) * 1000.0);
        if (!send_all(socket_, request.bytes()) || !receive(socket_, answer, patience_ms)) {
            throw std::runtime_error(name + ": the model reader service has stopped");
        }
    }
    Reading in(answer);
    detail::ChildOutcome outcome;
    outcome.message = in.get_bytes();
    outcome.status = in.get<int>();
    outcome.processor_seconds = in.get<double>();
    outcome.timed_out = in.get<std::uint8_t>() != 0;
    outcome.too_large = in.get<std::uint8_t>() != 0;
    outcome.start_error = in.get_text();
    return detail::model_from_outcome(outcome, name, reader, options.limits);
}

}  // namespace raster
