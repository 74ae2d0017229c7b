#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <linux/openat2.h>
#include <sys/syscall.h>
#include <stdexcept>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>

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

// Opens `path` below the confinement root so that nothing outside it can be reached, not even
// through a link or a directory swapped in after the check: the kernel's RESOLVE_BENEATH where
// there is one, else the resolved path with no link followed at its last step.
int open_confined(const fs::path& path, const fs::path& root, int flags) {
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, error), error);
    const fs::path relative = error ? fs::path() : resolved.lexically_relative(root);
    // The same words whether or not such a file exists outside: they tell an uploader nothing.
    if (relative.empty() || *relative.begin() == "..") refuse("lies outside '" + printable(root.string()) + "', where reading is confined");
    const int directory = ::open(root.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
    if (directory < 0) refuse(reason_from_errno(errno));
    open_how how{};
    how.flags = static_cast<std::uint64_t>(flags);
    how.resolve = RESOLVE_BENEATH | RESOLVE_NO_SYMLINKS | RESOLVE_NO_MAGICLINKS;
    long descriptor = ::syscall(SYS_openat2, directory, relative.c_str(), &how, sizeof how);
    const int opened_errno = errno;
    ::close(directory);
    if (descriptor < 0 && (opened_errno == ENOSYS || opened_errno == EPERM)) {
        descriptor = ::open(resolved.c_str(), flags | O_NOFOLLOW);  // an older kernel, or a sandbox that hides openat2
    } else if (descriptor < 0 && (opened_errno == EXDEV || opened_errno == ELOOP)) {
        refuse("lies outside '" + printable(root.string()) + "', where reading is confined");
    } else {
        errno = opened_errno;
    }
    return static_cast<int>(descriptor);
}

}  // namespace

InputFile::InputFile(const fs::path& path, const InputRules& rules) : record_{path, {}, rules.role} {
    // The kind is checked before opening: opening a device runs its driver (a tape rewinds).
    struct stat before {};
    if (rules.confine.empty()) {
        if (::stat(path.c_str(), &before) != 0) refuse(reason_from_errno(errno));
        if (!S_ISREG(before.st_mode)) refuse(kind_of(before.st_mode));
    }
    // O_NONBLOCK: should a FIFO take the file's place meanwhile, opening it must not wait.
    const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY;
    descriptor_ = rules.confine.empty() ? ::open(path.c_str(), flags) : open_confined(path, rules.confine, flags);
    if (descriptor_ < 0) refuse(reason_from_errno(errno));
    try {
        struct stat status {};
        if (::fstat(descriptor_, &status) != 0) refuse(reason_from_errno(errno));
        if (!S_ISREG(status.st_mode)) refuse(kind_of(status.st_mode));
        record_.identity = identity_from(status);
        if (rules.confine.empty() && record_.identity != identity_from(before)) refuse("changed while it was being opened");
        size_ = static_cast<std::uintmax_t>(status.st_size);
        if (size_ > rules.max_bytes) {
            refuse("is " + in_mib(size_) + ", more than the " + in_mib(rules.max_bytes) + " allowed");
        }
        const int file_flags = ::fcntl(descriptor_, F_GETFL);
        if (file_flags >= 0) ::fcntl(descriptor_, F_SETFL, file_flags & ~O_NONBLOCK);
        if (rules.signature != nullptr) {
            std::vector<std::uint8_t> head(rules.signature_bytes);
            std::size_t got = 0;
            while (got < head.size()) {
                const std::size_t more = read_some(std::span(head).subspan(got));
                if (more == 0) break;
                got += more;
            }
            head.resize(got);
            if (!rules.signature(head)) refuse(size_ == 0 ? "is empty, not " + rules.expected : "is not " + rules.expected);
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
    : descriptor_(std::exchange(other.descriptor_, -1)), size_(other.size_), position_(other.position_), record_(std::move(other.record_)) {}

std::size_t InputFile::read_some(std::span<std::uint8_t> buffer) {
    // Never past the size seen at opening: a file that grows meanwhile is not read without end.
    const std::size_t wanted = static_cast<std::size_t>(std::min<std::uintmax_t>(buffer.size(), size_ - std::min(position_, size_)));
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
            refuse(name_ + ":" + std::to_string(number_) + ": a line longer than " + in_mib(max_) + ", the most raster reads in one line");
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
    for (std::size_t got; (got = file.read_some(block)) > 0;) lines.feed({reinterpret_cast<const char*>(block.data()), got});
    lines.finish();
}

void for_each_line(std::string_view text, const std::string& name, std::size_t max_line_bytes,
                   const std::function<void(std::string_view line, std::size_t number)>& visit) {
    LineSplitter lines(name, max_line_bytes, visit);
    lines.feed(text);
    lines.finish();
}

std::vector<std::uint8_t> read_input_file(const fs::path& path, const InputRules& rules, std::vector<InputRecord>* sources) {
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
    if (!fs::is_directory(root, error)) throw std::runtime_error("'" + printable(path.string()) + "' is not a directory");
    return root;
}

std::string printable(std::string_view text, std::size_t limit) {
    std::size_t cut = std::min(text.size(), limit);
    while (cut < text.size() && cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // whole UTF-8 characters
    std::string shown;
    for (const char c : text.substr(0, cut)) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            char escaped[5];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            shown += escaped;
        } else {
            shown += c;
        }
    }
    if (cut < text.size()) shown += "...";
    return shown;
}

}  // namespace raster
