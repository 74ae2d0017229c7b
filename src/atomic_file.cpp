#include "atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace raster {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void fail(const fs::path& target, const std::string& reason) {
    throw std::runtime_error("cannot write '" + target.string() + "': " + reason);
}

fs::path directory_of(const fs::path& target) {
    return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

void check_destination(const fs::path& target) {
    if (target.empty() || !target.has_filename()) fail(target, "the path does not name a file");
    std::error_code error;
    const fs::path directory = directory_of(target);
    const fs::file_status status = fs::status(directory, error);
    if (status.type() == fs::file_type::not_found) {
        fail(target, "directory '" + directory.string() + "' does not exist");
    }
    if (!error && status.type() != fs::file_type::directory) {
        fail(target, "'" + directory.string() + "' is not a directory");
    }
    if (fs::is_directory(target, error)) fail(target, "it is a directory");
}

}  // namespace

AtomicFile::AtomicFile(fs::path target) : target_(std::move(target)) {
    check_destination(target_);
    std::string hidden_name = target_.filename().string();
    hidden_name.insert(0, 1, '.');
    hidden_name.append(".XXXXXX");
    std::string pattern = (directory_of(target_) / hidden_name).string();
    descriptor_ = ::mkstemp(pattern.data());
    if (descriptor_ < 0) fail(target_, std::strerror(errno));
    temporary_ = pattern;
    ::fchmod(descriptor_, 0644);  // mkstemp makes 0600; outputs are meant to be shared
}

AtomicFile::~AtomicFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
}

void AtomicFile::commit(std::span<const std::uint8_t> bytes) {
    while (!bytes.empty()) {
        const ::ssize_t written = ::write(descriptor_, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) fail(target_, std::strerror(written < 0 ? errno : EIO));
        bytes = bytes.subspan(static_cast<std::size_t>(written));
    }
    if (::fsync(descriptor_) != 0) fail(target_, std::strerror(errno));
    const int closed = ::close(descriptor_);
    descriptor_ = -1;
    if (closed != 0) fail(target_, std::strerror(errno));
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail(target_, std::strerror(errno));
    temporary_.clear();
}

}  // namespace raster
