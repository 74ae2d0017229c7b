// The bodies of input_file.hpp; stays whole as the one file named after that public header.
#include <raster/io/input_file.hpp>

#include "io/open_beneath.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raster {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void refuse(const std::string& reason) { throw std::runtime_error(reason); }

// What went wrong, as the end of a sentence about the file: "does not exist".
std::string reason_from_errno(int error) {
    if (error == ENOENT) return "does not exist";
    if (error == ENOTDIR) return "does not exist (a directory on its path is a file)";
    std::string text = std::strerror(error);
    if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    return "cannot be opened: " + text;
}

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory, not a file";
    if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

std::string in_mib(std::uintmax_t bytes) { return std::to_string((bytes + (1U << 20) - 1) >> 20) + " MiB"; }

FileIdentity identity_from(const struct stat& status) {
    return {static_cast<std::uint64_t>(status.st_dev), static_cast<std::uint64_t>(status.st_ino)};
}

std::string outside(const fs::path& root) {
    return "lies outside '" + printable(root.string()) + "', where reading is confined";
}

// Finds `path` below the confinement root so that nothing outside it can be reached, not even
// through a link or a directory swapped in after the check; an O_PATH descriptor, or -1.
int locate_confined(const fs::path& path, const fs::path& root) {
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, error), error);
    const fs::path relative = error ? fs::path() : resolved.lexically_relative(root);
    // The same words whether or not such a file exists outside: they tell an uploader nothing.
    if (relative.empty() || *relative.begin() == "..") refuse(outside(root));
    const int directory = ::open(root.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
    if (directory < 0) refuse(reason_from_errno(errno));
    const int descriptor = detail::open_beneath(directory, relative, detail::BeneathResolution::kernel_first);
    const int opened_errno = errno;
    ::close(directory);
    if (descriptor < 0 && (opened_errno == EXDEV || opened_errno == ELOOP)) refuse(outside(root));
    errno = opened_errno;
    return descriptor;
}

// Opens for reading the regular file that `located` (O_PATH, which opens nothing) names, once
// its kind is checked: opening a device runs its driver (a tape rewinds), a FIFO may wait.
int open_checked(int located, struct stat& before) {
    if (::fstat(located, &before) != 0) refuse(reason_from_errno(errno));
    if (!S_ISREG(before.st_mode)) refuse(kind_of(before.st_mode));
    const std::string reopen = "/proc/self/fd/" + std::to_string(located);
    // O_NONBLOCK: should anything but the checked file answer, opening it must not wait.
    const int descriptor = ::open(reopen.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (descriptor < 0 && errno == ENOENT && ::access("/proc/self/fd", F_OK) != 0) {
        refuse("cannot be opened: /proc is not mounted, and raster opens a file through it once its kind is checked");
    }
    if (descriptor < 0) refuse(reason_from_errno(errno));
    return descriptor;
}

}  // namespace

InputFile::InputFile(const fs::path& path, const InputRules& rules) : record_{path, {}, rules.role} {
    // Found with O_PATH, which opens nothing, so that the kind is known before the file is opened.
    const int located =
        rules.confine.empty() ? ::open(path.c_str(), O_PATH | O_CLOEXEC) : locate_confined(path, rules.confine);
    if (located < 0) refuse(reason_from_errno(errno));
    struct stat before {};
    try {
        descriptor_ = open_checked(located, before);
    } catch (...) {
        ::close(located);
        throw;
    }
    ::close(located);
    try {
        struct stat status {};
        if (::fstat(descriptor_, &status) != 0) refuse(reason_from_errno(errno));
        if (!S_ISREG(status.st_mode)) refuse(kind_of(status.st_mode));
        record_.identity = identity_from(status);
        if (record_.identity != identity_from(before)) refuse("changed while it was being opened");
        size_ = static_cast<std::uintmax_t>(status.st_size);
        if (size_ > rules.max_bytes) {
            refuse("is " + in_mib(size_) + ", more than the " + in_mib(rules.max_bytes) + " allowed");
        }
        const int file_flags = ::fcntl(descriptor_, F_GETFL);
        if (file_flags >= 0) ::fcntl(descriptor_, F_SETFL, file_flags & ~O_NONBLOCK);
        if (rules.signature != nullptr) {
            const std::vector<std::uint8_t> head = read_head(rules.signature_bytes);
            if (!rules.signature(head))
                refuse(size_ == 0 ? "is empty, not " + rules.expected : "is not " + rules.expected);
            rewind();
        }
    } catch (...) {
        ::close(descriptor_);
        throw;
    }
}

InputFile::~InputFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
}

InputFile::InputFile(InputFile&& other) noexcept
    : descriptor_(std::exchange(other.descriptor_, -1)), size_(other.size_), position_(other.position_),
      record_(std::move(other.record_)) {}

std::size_t InputFile::read_some(std::span<std::uint8_t> buffer) {
    // Never past the size seen at opening: a file that grows meanwhile is not read without end.
    const std::size_t wanted =
        static_cast<std::size_t>(std::min<std::uintmax_t>(buffer.size(), size_ - std::min(position_, size_)));
    if (wanted == 0) return 0;
    for (;;) {
        const ::ssize_t got = ::read(descriptor_, buffer.data(), wanted);
        if (got >= 0) {
            position_ += static_cast<std::uintmax_t>(got);
            return static_cast<std::size_t>(got);
        }
        if (errno != EINTR) refuse("cannot be read: " + std::string(std::strerror(errno)));
    }
}

std::vector<std::uint8_t> InputFile::read_all() {
    rewind();
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size_));
    std::size_t got = 0;
    while (got < bytes.size()) {
        const std::size_t more = read_some(std::span(bytes).subspan(got));
        if (more == 0) break;  // the file shrank since it was opened: keep what is there
        got += more;
    }
    bytes.resize(got);
    return bytes;
}

std::vector<std::uint8_t> InputFile::read_head(std::size_t bytes) {
    rewind();
    std::vector<std::uint8_t> head(bytes);
    std::size_t got = 0;
    while (got < head.size()) {
        const std::size_t more = read_some(std::span(head).subspan(got));
        if (more == 0) break;
        got += more;
    }
    head.resize(got);
    return head;
}

void InputFile::rewind() {
    if (::lseek(descriptor_, 0, SEEK_SET) != 0) refuse("cannot be read: " + std::string(std::strerror(errno)));
    position_ = 0;
}

namespace {

// Cuts text that arrives in pieces into lines ending at "\n", "\r\n" or a lone "\r", as
// tinyobjloader ends them, holding no line longer than the cap.
class LineSplitter {
public:
    using Visit = std::function<void(std::string_view line, std::size_t number)>;
    LineSplitter(const std::string& name, std::size_t max_line_bytes, const Visit& visit)
        : name_(name), max_(max_line_bytes), visit_(visit) {}

    void feed(std::string_view text) {
        if (after_cr_ && !text.empty() && text.front() == '\n') text.remove_prefix(1);
        if (!text.empty()) after_cr_ = false;
        for (std::size_t end; (end = text.find_first_of("\r\n")) != std::string_view::npos;) {
            end_line(text.substr(0, end));
            const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
            after_cr_ = text[end] == '\r' && end + 1 == text.size();  // its '\n' may open the next piece
            text.remove_prefix(end + (crlf ? 2 : 1));
        }
        if (partial_.size() + text.size() > max_) end_line(text);  // refuses
        partial_ += text;
    }
    void finish() {
        if (!partial_.empty()) end_line({});
    }

private:
    void end_line(std::string_view piece) {
        if (partial_.size() + piece.size() > max_) {
            refuse(name_ + ":" + std::to_string(number_) + ": a line longer than " + in_mib(max_) +
                   ", the most raster reads in one line");
        }
        if (partial_.empty()) {
            visit_(piece, number_);
        } else {
            partial_ += piece;
            visit_(partial_, number_);
            partial_.clear();
        }
        ++number_;
    }

    const std::string& name_;
    std::size_t max_;
    const Visit& visit_;
    std::string partial_;  // the start of a line that runs past the piece
    std::size_t number_ = 1;
    bool after_cr_ = false;
};

}  // namespace

void for_each_line(InputFile& file, const std::string& name, std::size_t max_line_bytes,
                   const std::function<void(std::string_view line, std::size_t number)>& visit) {
    file.rewind();
    LineSplitter lines(name, max_line_bytes, visit);
    std::vector<std::uint8_t> block(std::size_t{1} << 16);
    for (std::size_t got; (got = file.read_some(block)) > 0;)
        lines.feed({reinterpret_cast<const char*>(block.data()), got});
    lines.finish();
}

void for_each_line(std::string_view text, const std::string& name, std::size_t max_line_bytes,
                   const std::function<void(std::string_view line, std::size_t number)>& visit) {
    LineSplitter lines(name, max_line_bytes, visit);
    lines.feed(text);
    lines.finish();
}

std::vector<std::uint8_t> read_input_file(const fs::path& path, const InputRules& rules,
                                          std::vector<InputRecord>* sources) {
    InputFile file(path, rules);
    std::vector<std::uint8_t> bytes = file.read_all();
    if (sources != nullptr) sources->push_back(file.record());
    return bytes;
}

bool identity_of(const fs::path& path, FileIdentity& identity) {
    struct stat status {};
    if (::stat(path.c_str(), &status) != 0) return false;
    identity = {static_cast<std::uint64_t>(status.st_dev), static_cast<std::uint64_t>(status.st_ino)};
    return true;
}

fs::path confinement_root(const fs::path& path) {
    std::error_code error;
    const fs::path root = fs::canonical(path, error);
    if (error) throw std::runtime_error("'" + printable(path.string()) + "' " + reason_from_errno(error.value()));
    if (!fs::is_directory(root, error))
        throw std::runtime_error("'" + printable(path.string()) + "' is not a directory");
    return root;
}

namespace {

// The length of the well-formed UTF-8 character at the start of `text` (Unicode's table 3-7:
// no overlong forms, surrogates or code points past U+10FFFF), or 0 when it starts with none.
std::size_t utf8_length(std::string_view text) {
    const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0U; };
    const auto within = [](unsigned value, unsigned low, unsigned high) { return value >= low && value <= high; };
    const unsigned lead = byte(0);
    if (lead < 0x80) return 1;
    if (within(lead, 0xC2, 0xDF)) return within(byte(1), 0x80, 0xBF) ? 2 : 0;
    if (within(lead, 0xE0, 0xEF)) {
        const unsigned low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
        return within(byte(1), low, high) && within(byte(2), 0x80, 0xBF) ? 3 : 0;
    }
    if (within(lead, 0xF0, 0xF4)) {
        const unsigned low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
        return within(byte(1), low, high) && within(byte(2), 0x80, 0xBF) && within(byte(3), 0x80, 0xBF) ? 4 : 0;
    }
    return 0;
}

void append_escaped(std::string& shown, std::string_view bytes) {
    for (const char c : bytes) {
        char escaped[5];
        std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
        shown += escaped;
    }
}

}  // namespace

std::string printable(std::string_view text, std::size_t limit) {
    std::string shown;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t length = utf8_length(text.substr(at));
        // A byte that starts no character stands alone, as \xNN, and the next byte starts afresh.
        const std::size_t step = std::max<std::size_t>(length, 1);
        if (step > limit - std::min(at, limit)) break;  // whole characters only
        const std::string_view piece = text.substr(at, step);
        const auto lead = static_cast<unsigned char>(piece[0]);
        // C0 and C1 controls (U+0080-U+009F is C2 80-C2 9F) steer a terminal: CSI is C2 9B.
        const bool control =
            lead < 0x20 || lead == 0x7f || (lead == 0xC2 && length == 2 && static_cast<unsigned char>(piece[1]) < 0xA0);
        if (length == 0 || control) {
            append_escaped(shown, piece);
        } else {
            shown += piece;
        }
        at += step;
    }
    if (at < text.size()) shown += "...";
    return shown;
}

}  // namespace raster
