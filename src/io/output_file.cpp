#include <raster/io/output_file.hpp>

#include <raster/io/held_signals.hpp>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raster {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void fail(const fs::path& target, const std::string& reason) {
    throw std::runtime_error("cannot write '" + printable(target.string()) + "': " + reason);
}

fs::path directory_of(const fs::path& target) {
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISLNK(mode)) return "a symbolic link (--follow-symlinks writes to the file it names)";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

// Follows a chain of links, each resolved against the directory that holds it.
fs::path resolve_links(const fs::path& path) {
    fs::path current = path;
    for (int hop = 0; hop < 40; ++hop) {
        struct stat status {};
        if (::lstat(current.c_str(), &status) != 0 || !S_ISLNK(status.st_mode)) return current;
        std::error_code error;
        const fs::path next = fs::read_symlink(current, error);
        if (error) fail(path, error.message());
        current = next.is_absolute() ? next : directory_of(current) / next;
    }
    fail(path, "too many levels of symbolic links");
}

// The file to write after the policy on links, checked: its directory exists, and it is
// absent or a regular file. Returns its status in `existing` when it exists.
fs::path checked_destination(const fs::path& path, OutputPolicy policy, std::span<const InputRecord> inputs,
                             std::optional<struct stat>& existing) {
    if (path.empty() || !path.has_filename()) fail(path, "the path does not name a file");
    const fs::path target = policy.follow_symlinks ? resolve_links(path) : path;
    const fs::path directory = directory_of(target);
    struct stat status {};
    if (::stat(directory.c_str(), &status) != 0) {
        if (errno == ENOENT) fail(path, "directory '" + directory.string() + "' does not exist");
        if (errno == ENOTDIR) fail(path, "'" + directory.string() + "' is not a directory");
        fail(path, std::strerror(errno));
    }
    if (!S_ISDIR(status.st_mode)) fail(path, "'" + directory.string() + "' is not a directory");
    existing.reset();
    if (::lstat(target.c_str(), &status) == 0) {
        if (!S_ISREG(status.st_mode)) fail(path, std::string("it is ") + kind_of(status.st_mode));
        const FileIdentity identity{static_cast<std::uint64_t>(status.st_dev),
                                    static_cast<std::uint64_t>(status.st_ino)};
        for (const InputRecord& input : inputs) {
            if (input.identity != identity) continue;
            const std::string same = input.path == path ? "" : " '" + printable(input.path.string()) + "'";
            fail(path, "it is the " + input.role + same + " this run reads; choose another output name");
        }
        existing = status;
    } else if (errno != ENOENT) {
        fail(path, std::strerror(errno));
    }
    return target;
}

// A new file with a short random name beside the target (so names up to the filesystem's
// limit still work), removed on destruction unless released.
class TemporaryFile {
public:
    TemporaryFile(const fs::path& target, mode_t mode) : target_(target) {
        std::random_device random;
        for (int attempt = 0; attempt < 100; ++attempt) {
            char name[32];
            std::snprintf(name, sizeof name, ".raster-%08x.tmp", random());
            path_ = directory_of(target) / name;
            descriptor_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
            if (descriptor_ >= 0 || errno != EEXIST) break;
        }
        if (descriptor_ < 0) {
            path_.clear();
            fail(target, std::strerror(errno));
        }
    }
    ~TemporaryFile() {
        if (descriptor_ >= 0) ::close(descriptor_);
        if (!path_.empty()) ::unlink(path_.c_str());
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    [[nodiscard]] int descriptor() const { return descriptor_; }

    void write_all(std::span<const std::uint8_t> bytes) const {
        while (!bytes.empty()) {
            const ::ssize_t written = ::write(descriptor_, bytes.data(), bytes.size());
            if (written < 0 && errno == EINTR) continue;
            if (written <= 0) fail(target_, std::strerror(written < 0 ? errno : EIO));
            bytes = bytes.subspan(static_cast<std::size_t>(written));
        }
    }

    // Flushes, closes and renames the file over `destination`.
    void commit(const fs::path& destination) {
        if (::fsync(descriptor_) != 0) fail(target_, std::strerror(errno));
        const int closed = ::close(descriptor_);
        descriptor_ = -1;
        if (closed != 0) fail(target_, std::strerror(errno));
        if (::rename(path_.c_str(), destination.c_str()) != 0) fail(target_, std::strerror(errno));
        path_.clear();
        // Make the rename itself durable; a directory that cannot be synced is no error.
        const int directory = ::open(directory_of(destination).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        if (directory >= 0) {
            ::fsync(directory);
            ::close(directory);
        }
    }

private:
    fs::path target_;
    fs::path path_;
    int descriptor_ = -1;
};

}  // namespace

void check_output_path(const fs::path& path, OutputPolicy policy, std::span<const InputRecord> inputs) {
    std::optional<struct stat> existing;
    const fs::path target = checked_destination(path, policy, inputs, existing);
    // Probe that the directory takes a new file; interrupts wait until the probe is gone.
    const HeldSignals held;
    const TemporaryFile probe(target, 0600);
}

void write_output_file(const fs::path& path, std::span<const std::uint8_t> bytes, OutputPolicy policy,
                       std::span<const InputRecord> inputs) {
    std::optional<struct stat> existing;
    const fs::path target = checked_destination(path, policy, inputs, existing);
    // Process-wide: a signal landing on any worker thread waits as well.
    const HeldSignals held;
    TemporaryFile file(target, existing ? 0600 : 0666);
    if (existing) {
        // Keep the replaced file's owner (where allowed) and mode.
        if (::fchown(file.descriptor(), existing->st_uid, existing->st_gid) != 0) {
            // Not the owner: the file becomes ours, as any editor would make it.
        }
        if (::fchmod(file.descriptor(), existing->st_mode & 07777) != 0) fail(path, std::strerror(errno));
    }
    file.write_all(bytes);
    file.commit(target);
}

}  // namespace raster
