#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

// Plain values as bytes between raster's own processes (the model's trip, the reader service's
// requests): the same program on both ends, so no byte order or padding is negotiated.
namespace raster::detail {

// Writes values, arrays and text, each array and text its length first: appended to a byte
// vector, into a span sized beforehand, or only counted, so that the span's size is exact.
class WireWriter {
public:
    WireWriter() = default;  // counts
    explicit WireWriter(std::vector<std::uint8_t>& out) : grow_(&out) {}
    explicit WireWriter(std::span<std::uint8_t> into) : into_(into) {}

    template <typename T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    template <typename T>
    void array(const std::vector<T>& items) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(static_cast<std::uint64_t>(items.size()));
        bytes(items.data(), items.size() * sizeof(T));
    }
    void array(std::span<const std::uint8_t> items) {
        value(static_cast<std::uint64_t>(items.size()));
        bytes(items.data(), items.size());
    }
    void text(const std::string& s) {
        value(static_cast<std::uint64_t>(s.size()));
        bytes(s.data(), s.size());
    }
    // The bytes written or counted so far.
    [[nodiscard]] std::size_t size() const noexcept { return size_; }

private:
    void bytes(const void* data, std::size_t size) {
        const auto* first = static_cast<const std::uint8_t*>(data);
        if (grow_ != nullptr && size > 0) grow_->insert(grow_->end(), first, first + size);
        if (into_.data() != nullptr && size > 0) {
            if (size > into_.size() - size_) throw std::length_error("the wire's bytes were counted short");
            std::memcpy(into_.data() + size_, first, size);
        }
        size_ += size;
    }
    std::vector<std::uint8_t>* grow_ = nullptr;
    std::span<std::uint8_t> into_;
    std::size_t size_ = 0;
};

// Walks bytes as values of T, copied out one by one: a vector built from a pair of them is
// allocated once and written once, neither zeroed first nor read through a misaligned pointer.
template <typename T>
class BytesAs {
public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = const T*;
    using reference = T;

    explicit BytesAs(const std::uint8_t* at) : at_(at) {}
    T operator*() const noexcept {
        T v;
        std::memcpy(&v, at_, sizeof v);
        return v;
    }
    BytesAs& operator++() noexcept {
        at_ += sizeof(T);
        return *this;
    }
    BytesAs operator++(int) noexcept {
        BytesAs was = *this;
        at_ += sizeof(T);
        return was;
    }
    BytesAs& operator+=(difference_type n) noexcept {
        at_ += n * static_cast<difference_type>(sizeof(T));
        return *this;
    }
    friend difference_type operator-(BytesAs a, BytesAs b) noexcept {
        return (a.at_ - b.at_) / static_cast<difference_type>(sizeof(T));
    }
    friend bool operator==(BytesAs a, BytesAs b) noexcept { return a.at_ == b.at_; }

private:
    const std::uint8_t* at_;
};

// Reads them back in the same order, every length checked against the bytes that remain.
class WireReader {
public:
    explicit WireReader(std::span<const std::uint8_t> bytes) : rest_(bytes) {}

    template <typename T>
    T value() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        std::memcpy(&v, take(sizeof v).data(), sizeof v);
        return v;
    }
    template <typename T>
    std::vector<T> array() {
        const auto count = value<std::uint64_t>();
        if (count > rest_.size() / sizeof(T)) broken();
        const std::uint8_t* first = take(static_cast<std::size_t>(count) * sizeof(T)).data();
        return std::vector<T>(BytesAs<T>(first), BytesAs<T>(first + count * sizeof(T)));
    }
    std::string text() {
        const auto count = value<std::uint64_t>();
        if (count > rest_.size()) broken();
        const auto bytes = take(static_cast<std::size_t>(count));
        return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
    }
    [[nodiscard]] bool done() const noexcept { return rest_.empty(); }
    [[nodiscard]] std::size_t left() const noexcept { return rest_.size(); }
    [[noreturn]] static void broken() {
        throw std::runtime_error("what the reader process sent does not hold together");
    }

private:
    std::span<const std::uint8_t> take(std::size_t size) {
        if (size > rest_.size()) broken();
        const auto taken = rest_.first(size);
        rest_ = rest_.subspan(size);
        return taken;
    }
    std::span<const std::uint8_t> rest_;
};

}  // namespace raster::detail
