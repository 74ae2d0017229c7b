#include "io/ply/ply_bytes.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace raster::detail {

PlyBytes::PlyBytes(std::function<std::size_t(std::span<std::uint8_t>)> fill, std::uint64_t size)
    : fill_(std::move(fill)), size_(size) {}

std::span<const std::uint8_t> PlyBytes::ahead(std::size_t bytes) {
    if (end_ - begin_ < bytes && !at_end_) {
        // What is left moves to the front, and the block fills behind it.
        if (begin_ > 0) {
            std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
            end_ -= begin_;
            begin_ = 0;
        }
        const std::size_t block =
            std::max<std::size_t>(bytes, static_cast<std::size_t>(std::min<std::uint64_t>(kPlyBlockBytes, size_)));
        if (buffer_.size() < block) buffer_.resize(block);
        while (end_ < buffer_.size()) {
            const std::size_t got = fill_(std::span<std::uint8_t>(buffer_.data() + end_, buffer_.size() - end_));
            if (got == 0) {
                at_end_ = true;
                break;
            }
            end_ += got;
        }
    }
    return {buffer_.data() + begin_, end_ - begin_};
}

bool PlyBytes::line(std::string_view& text, bool& ended) {
    std::size_t looked = 0;  // bytes already searched for the line's end
    for (;;) {
        const std::span<const std::uint8_t> held(buffer_.data() + begin_, end_ - begin_);
        const auto* newline =
            static_cast<const std::uint8_t*>(std::memchr(held.data() + looked, '\n', held.size() - looked));
        if (newline != nullptr || at_end_) {
            const std::size_t length =
                newline != nullptr ? static_cast<std::size_t>(newline - held.data()) : held.size();
            if (length == 0 && newline == nullptr) return false;
            text = std::string_view(reinterpret_cast<const char*>(held.data()), length);
            if (text.ends_with('\r')) text.remove_suffix(1);
            ended = newline != nullptr;
            advance(length + (ended ? 1 : 0));
            return true;
        }
        if (held.size() >= kPlyBlockBytes)
            throw std::runtime_error("a line longer than " + std::to_string(kPlyBlockBytes >> 20) + " MiB");
        looked = held.size();
        static_cast<void>(ahead(held.size() + 1));
    }
}

}  // namespace raster::detail
