#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

// The model's bytes in memory the reader child shares with the process that waits for it, so
// that hundreds of megabytes cross without a pipe's copies (doc/conventions.md#reader-process).
namespace raster::detail {

// A memory file of a fixed size, sealed so that neither side can shrink or grow it: the child
// writes through a mapping (which no file-size limit stops) and the other side maps what it wrote.
class SharedBytes {
public:
    SharedBytes() = default;
    // Adopts a descriptor received from another process (-1: none).
    explicit SharedBytes(int descriptor) noexcept : descriptor_(descriptor) {}
    SharedBytes(SharedBytes&& other) noexcept : descriptor_(other.release()) {}
    SharedBytes& operator=(SharedBytes&& other) noexcept;
    SharedBytes(const SharedBytes&) = delete;
    SharedBytes& operator=(const SharedBytes&) = delete;
    ~SharedBytes();

    // A new one of `capacity` bytes, which take no memory until written; throws
    // std::runtime_error with the system's reason when there can be none.
    [[nodiscard]] static SharedBytes create(std::uint64_t capacity);

    [[nodiscard]] int descriptor() const noexcept { return descriptor_; }
    [[nodiscard]] int release() noexcept;

private:
    int descriptor_ = -1;
};

// The first bytes of a SharedBytes, mapped until it ends.
class SharedMapping {
public:
    // Writable, for the child; throws std::bad_alloc when its address space has no room.
    [[nodiscard]] static SharedMapping for_writing(const SharedBytes& shared, std::size_t size);
    // Read-only, for the waiting side; throws std::runtime_error (one line) when the bytes are
    // not all there or their file could still shrink under the mapping.
    [[nodiscard]] static SharedMapping for_reading(const SharedBytes& shared, std::size_t size);
    SharedMapping(SharedMapping&& other) noexcept : bytes_(other.bytes_) { other.bytes_ = {}; }
    SharedMapping(const SharedMapping&) = delete;
    SharedMapping& operator=(const SharedMapping&) = delete;
    SharedMapping& operator=(SharedMapping&&) = delete;
    ~SharedMapping();

    [[nodiscard]] std::span<std::uint8_t> bytes() const noexcept { return bytes_; }

private:
    explicit SharedMapping(std::span<std::uint8_t> bytes) noexcept : bytes_(bytes) {}
    std::span<std::uint8_t> bytes_;
};

}  // namespace raster::detail
