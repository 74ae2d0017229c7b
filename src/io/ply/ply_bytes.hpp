#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

// A PLY file read once from the start in blocks of a few MiB, never held whole: what the reader
// needs next is contiguous in the block (doc/conventions.md#ply-reader).
namespace raster::detail {

class PlyBytes {
public:
    // `fill` puts the file's next bytes in its span and says how many; 0 at the end. `size` is
    // the file's size when it was opened: counts are checked against it.
    PlyBytes(std::function<std::size_t(std::span<std::uint8_t>)> fill, std::uint64_t size);

    // At least `bytes` contiguous bytes from here, or fewer only where the file ends first.
    [[nodiscard]] std::span<const std::uint8_t> ahead(std::size_t bytes);
    void advance(std::size_t bytes) noexcept {
        begin_ += bytes;
        offset_ += bytes;
    }
    // The offset in the file of the next byte, and the bytes after it by the file's size.
    [[nodiscard]] std::uint64_t offset() const noexcept { return offset_; }
    [[nodiscard]] std::uint64_t left() const noexcept { return offset_ < size_ ? size_ - offset_ : 0; }

    // The next line without its "\n" (nor "\r\n"); false at the end of the data. `ended` says
    // whether a "\n" ended it (a last line without one may be cut short). Throws
    // std::runtime_error for a line longer than a block.
    bool line(std::string_view& text, bool& ended);

private:
    std::function<std::size_t(std::span<std::uint8_t>)> fill_;
    std::uint64_t size_;
    std::vector<std::uint8_t> buffer_;
    std::size_t begin_ = 0, end_ = 0;
    std::uint64_t offset_ = 0;
    bool at_end_ = false;
};

// The block size, which is also the longest line an ASCII PLY may have.
inline constexpr std::size_t kPlyBlockBytes = std::size_t{4} << 20;

}  // namespace raster::detail
