#include <raster/io/reader_service.hpp>

#include "io/model_reading.hpp"
#include "io/reader_process.hpp"
#include "io/shared_bytes.hpp"
#include "io/wire_bytes.hpp"

#include <raster/io/input_file.hpp>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <initializer_list>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <sys/wait.h>
#include <unistd.h>

namespace raster {
namespace {

// Sends `bytes`, with `descriptor` (unless -1) riding on the first of them.
bool send_bytes(int socket, std::span<const std::uint8_t> bytes, int descriptor) {
    while (!bytes.empty()) {
        iovec piece{const_cast<std::uint8_t*>(bytes.data()), bytes.size()};
        msghdr message{};
        message.msg_iov = &piece;
        message.msg_iovlen = 1;
        alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
        if (descriptor >= 0) {
            message.msg_control = control;
            message.msg_controllen = sizeof control;
            cmsghdr* passed = CMSG_FIRSTHDR(&message);
            passed->cmsg_level = SOL_SOCKET;
            passed->cmsg_type = SCM_RIGHTS;
            passed->cmsg_len = CMSG_LEN(sizeof(int));
            std::memcpy(CMSG_DATA(passed), &descriptor, sizeof descriptor);
        }
        const ::ssize_t n = ::sendmsg(socket, &message, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        descriptor = -1;  // it went with the first byte
        bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
    return true;
}

// One message: its length, then its pieces as they are, none copied into another; `descriptor`
// (the model's shared memory, unless -1) goes along.
bool send_all(int socket, std::initializer_list<std::span<const std::uint8_t>> pieces, int descriptor = -1) {
    std::uint64_t length = 0;
    for (const auto& piece : pieces) length += piece.size();
    if (!send_bytes(socket, {reinterpret_cast<const std::uint8_t*>(&length), sizeof length}, descriptor)) return false;
    for (std::span<const std::uint8_t> piece : pieces) {
        if (!send_bytes(socket, piece, -1)) return false;
    }
    return true;
}

// Receives up to `size` bytes; a descriptor that came along is kept in `shared` (a second one is closed).
::ssize_t receive_some(int socket, std::uint8_t* into, std::size_t size, detail::SharedBytes& shared) {
    iovec piece{into, size};
    msghdr message{};
    message.msg_iov = &piece;
    message.msg_iovlen = 1;
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(int))] = {};
    message.msg_control = control;
    message.msg_controllen = sizeof control;
    const ::ssize_t n = ::recvmsg(socket, &message, MSG_CMSG_CLOEXEC);
    for (cmsghdr* passed = n > 0 ? CMSG_FIRSTHDR(&message) : nullptr; passed != nullptr;
         passed = CMSG_NXTHDR(&message, passed)) {
        if (passed->cmsg_level != SOL_SOCKET || passed->cmsg_type != SCM_RIGHTS) continue;
        const std::size_t count = (passed->cmsg_len - CMSG_LEN(0)) / sizeof(int);
        for (std::size_t i = 0; i < count; ++i) {
            int descriptor = -1;
            std::memcpy(&descriptor, CMSG_DATA(passed) + i * sizeof(int), sizeof descriptor);
            if (shared.descriptor() < 0) {
                shared = detail::SharedBytes(descriptor);
            } else {
                ::close(descriptor);
            }
        }
    }
    return n;
}

// One whole message, or false at the end of the stream or after `timeout_ms` (-1: none).
bool receive(int socket, std::vector<std::uint8_t>& message, int timeout_ms, detail::SharedBytes& shared) {
    std::uint64_t length = 0;
    std::size_t got = 0;
    const auto fill = [&](std::uint8_t* into, std::size_t size) {
        for (got = 0; got < size;) {
            pollfd ready{socket, POLLIN, 0};
            const int polled = ::poll(&ready, 1, timeout_ms);
            if (polled < 0 && errno == EINTR) continue;
            if (polled <= 0) return false;
            const ::ssize_t n = receive_some(socket, into + got, size - got, shared);
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
    detail::SharedBytes none;  // a request brings no descriptor
    while (receive(socket, request, -1, none)) {
        detail::ChildOutcome outcome;
        try {
            detail::WireReader in(request);
            const std::filesystem::path path = in.text();
            ObjOptions options;
            options.crease_degrees = in.value<double>();
            options.load_textures = in.value<std::uint8_t>() != 0;
            options.max_texels = in.value<std::size_t>();
            options.max_line_bytes = in.value<std::size_t>();
            options.threads = in.value<std::size_t>();
            options.range_bytes = in.value<std::size_t>();
            options.confine = in.text();
            options.limits.max_memory = in.value<std::uint64_t>();
            options.limits.max_seconds = in.value<double>();
            outcome = detail::run_reader_child([&] { return detail::read_model_here(path, options); }, options.limits);
        } catch (const std::exception& problem) {
            outcome.start_error = problem.what();
        }
        std::vector<std::uint8_t> ending;  // how the reader ended; what it sent follows as it is
        detail::WireWriter out(ending);
        out.value(outcome.status);
        out.value(outcome.processor_seconds);
        out.value(static_cast<std::uint8_t>(outcome.timed_out));
        out.value(static_cast<std::uint8_t>(outcome.too_large));
        out.text(outcome.start_error);
        if (!send_all(socket, {ending, outcome.message}, outcome.shared.descriptor())) break;
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

Model ReaderService::read(const std::filesystem::path& path, const ObjOptions& options,
                          double* processor_seconds) const {
    const std::string name = printable(path.string());
    const std::string reader = detail::reader_name(path);
    std::vector<std::uint8_t> request;
    detail::WireWriter out(request);
    out.text(path.string());
    out.value(options.crease_degrees);
    out.value(static_cast<std::uint8_t>(options.load_textures));
    out.value(options.max_texels);
    out.value(options.max_line_bytes);
    out.value(options.threads);
    out.value(options.range_bytes);
    out.text(options.confine.string());
    out.value(options.limits.max_memory);
    out.value(options.limits.max_seconds);
    std::vector<std::uint8_t> answer;
    detail::ChildOutcome outcome;
    {
        const std::lock_guard<std::mutex> mine(turn_);
        // The service enforces the limits; a minute more here only guards against its own end.
        const int patience_ms = static_cast<int>(std::min(options.limits.max_seconds + 60.0, 2.0e6) * 1000.0);
        if (!send_all(socket_, {request}) || !receive(socket_, answer, patience_ms, outcome.shared)) {
            throw std::runtime_error(name + ": the model reader service has stopped");
        }
    }
    detail::WireReader in(answer);
    outcome.status = in.value<int>();
    outcome.processor_seconds = in.value<double>();
    outcome.timed_out = in.value<std::uint8_t>() != 0;
    outcome.too_large = in.value<std::uint8_t>() != 0;
    outcome.start_error = in.text();
    answer.erase(answer.begin(),
                 answer.end() - static_cast<std::ptrdiff_t>(in.left()));  // the rest is what the reader sent
    outcome.message = std::move(answer);
    if (processor_seconds != nullptr) *processor_seconds = outcome.processor_seconds;
    return detail::model_from_outcome(outcome, name, reader, options.limits);
}

}  // namespace raster
