#include "io/shared_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace raster::detail {

namespace {

constexpr int kSizeSeals = F_SEAL_SHRINK | F_SEAL_GROW;

std::span<std::uint8_t> mapped(const SharedBytes& shared, std::size_t size, int protection) {
    if (size == 0) return {};
    // Populated at once: one call instead of a page fault for every 4 KiB of the model.
    void* at = ::mmap(nullptr, size, protection, MAP_SHARED | MAP_POPULATE, shared.descriptor(), 0);
    if (at == MAP_FAILED) return {};
    return {static_cast<std::uint8_t*>(at), size};
}

}  // namespace

SharedBytes& SharedBytes::operator=(SharedBytes&& other) noexcept {
    if (this != &other) {
        if (descriptor_ >= 0) ::close(descriptor_);
        descriptor_ = other.release();
    }
    return *this;
}

SharedBytes::~SharedBytes() {
    if (descriptor_ >= 0) ::close(descriptor_);
}

int SharedBytes::release() noexcept {
    const int descriptor = descriptor_;
    descriptor_ = -1;
    return descriptor;
}

SharedBytes SharedBytes::create(std::uint64_t capacity) {
    SharedBytes shared(::memfd_create("raster-model", MFD_CLOEXEC | MFD_ALLOW_SEALING));
    const auto fail = [](const char* step) {
        throw std::runtime_error(std::string("cannot ") + step +
                                 " the memory the model comes back in: " + std::strerror(errno));
    };
    if (shared.descriptor_ < 0) fail("create");
    if (::ftruncate(shared.descriptor_, static_cast<off_t>(capacity)) != 0) fail("size");
    if (::fcntl(shared.descriptor_, F_ADD_SEALS, kSizeSeals | F_SEAL_SEAL) != 0) fail("seal");
    return shared;
}

SharedMapping SharedMapping::for_writing(const SharedBytes& shared, std::size_t size) {
    const std::span<std::uint8_t> bytes = mapped(shared, size, PROT_READ | PROT_WRITE);
    if (size > 0 && bytes.empty()) throw std::bad_alloc();
    return SharedMapping(bytes);
}

SharedMapping SharedMapping::for_reading(const SharedBytes& shared, std::size_t size) {
    struct stat file {};
    const int seals = ::fcntl(shared.descriptor(), F_GET_SEALS);
    if (seals < 0 || (seals & kSizeSeals) != kSizeSeals || ::fstat(shared.descriptor(), &file) != 0 ||
        file.st_size < 0 || static_cast<std::uint64_t>(file.st_size) < size)
        throw std::runtime_error("the memory the model came back in is not what was made for it");
    const std::span<std::uint8_t> bytes = mapped(shared, size, PROT_READ);
    if (size > 0 && bytes.empty())
        throw std::runtime_error(std::string("cannot map the memory the model came back in: ") + std::strerror(errno));
    return SharedMapping(bytes);
}

SharedMapping::~SharedMapping() {
    if (!bytes_.empty()) ::munmap(bytes_.data(), bytes_.size());
}

}  // namespace raster::detail
