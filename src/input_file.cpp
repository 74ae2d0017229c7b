#include <raster/input_file.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>

namespace raster {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void refuse(const std::string& reason) { throw std::runtime_error(reason); }

// strerror's text with a small first letter, to sit inside our sentences.
std::string reason_from_errno(int error) {
    if (error == ENOENT) return "no such file";
    std::string text = std::strerror(error);
    if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
}

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory, not a file";
    if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
    if (S_ISSOCK(mode)) return "is a socket, not a regular file";
    return "is not a regular file";
}

std::string in_mib(std::uintmax_t bytes) { return std::to_string((bytes + (1U << 20) - 1) >> 20) + " MiB"; }

// The path to open: under confinement, the resolved path, which must lie inside the root.
fs::path path_to_open(const fs::path& path, const InputRules& rules) {
    if (rules.confine.empty()) return path;
    std::error_code error;
    const fs::path resolved = fs::canonical(path, error);
    if (error) refuse(reason_from_errno(error.value()));
    const fs::path relative = resolved.lexically_relative(rules.confine);
    if (relative.empty() || *relative.begin() == "..") refuse("lies outside '" + rules.confine.string() + "', where reading is confined");
    return resolved;
}

}  // namespace

InputFile::InputFile(const fs::path& path, const InputRules& rules) : record_{path, {}, rules.role} {
    const fs::path opened = path_to_open(path, rules);
    // O_NONBLOCK: opening a FIFO must not wait for a writer; O_NOFOLLOW under confinement,
    // whose path has no links left.
    const int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY | (rules.confine.empty() ? 0 : O_NOFOLLOW);
    descriptor_ = ::open(opened.c_str(), flags);
    if (descriptor_ < 0) refuse(reason_from_errno(errno));
    try {
        struct stat status {};
        if (::fstat(descriptor_, &status) != 0) refuse(reason_from_errno(errno));
        if (!S_ISREG(status.st_mode)) refuse(kind_of(status.st_mode));
        record_.identity = {static_cast<std::uint64_t>(status.st_dev), static_cast<std::uint64_t>(status.st_ino)};
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
    : descriptor_(std::exchange(other.descriptor_, -1)), size_(other.size_), record_(std::move(other.record_)) {}

std::size_t InputFile::read_some(std::span<std::uint8_t> buffer) {
    for (;;) {
        const ::ssize_t got = ::read(descriptor_, buffer.data(), buffer.size());
        if (got >= 0) return static_cast<std::size_t>(got);
        if (errno != EINTR) refuse("cannot read: " + reason_from_errno(errno));
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
    if (::lseek(descriptor_, 0, SEEK_SET) != 0) refuse("cannot read: " + reason_from_errno(errno));
}

void for_each_line(InputFile& file, const std::string& name, std::size_t max_line_bytes,
                   const std::function<void(std::string_view line, std::size_t number)>& visit) {
    file.rewind();
    std::vector<std::uint8_t> block(std::size_t{1} << 16);
    std::string partial;  // the start of a line that runs past the block
    std::size_t number = 1;
    const auto too_long = [&] {
        refuse(name + ":" + std::to_string(number) + ": a line longer than " + in_mib(max_line_bytes) +
               ", the most raster reads in one line");
    };
    for (std::size_t got; (got = file.read_some(block)) > 0;) {
        const std::string_view text(reinterpret_cast<const char*>(block.data()), got);
        std::size_t start = 0;
        for (std::size_t end; (end = text.find('\n', start)) != std::string_view::npos; start = end + 1, ++number) {
            const std::string_view piece = text.substr(start, end - start);
            if (partial.size() + piece.size() > max_line_bytes) too_long();
            if (partial.empty()) {
                visit(piece, number);
            } else {
                partial += piece;
                visit(partial, number);
                partial.clear();
            }
        }
        if (partial.size() + (text.size() - start) > max_line_bytes) too_long();
        partial += text.substr(start);
    }
    if (!partial.empty()) visit(partial, number);
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
    if (error) throw std::runtime_error("'" + printable(path.string()) + "': " + reason_from_errno(error.value()));
    if (!fs::is_directory(root, error)) throw std::runtime_error("'" + printable(path.string()) + "' is not a directory");
    return root;
}

std::string printable(std::string_view text, std::size_t limit) {
    std::string shown;
    for (const char c : text.substr(0, std::min(text.size(), limit))) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            char escaped[5];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
            shown += escaped;
        } else {
            shown += c;
        }
    }
    if (text.size() > limit) shown += "...";
    return shown;
}

}  // namespace raster
