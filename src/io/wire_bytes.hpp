#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

// Plain values as bytes between raster's own processes (the model's trip, the reader service's
// requests): the same program on both ends, so no byte order or padding is negotiated.
namespace raster::detail {

// Appends values, arrays and text to a byte vector, each array and text its length first.
class WireWriter {
public:
    explicit WireWriter(std::vector<std::uint8_t>& out) : out_(out) {}

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

private:
    void bytes(const void* data, std::size_t size) {
        const auto* first = static_cast<const std::uint8_t*>(data);
        if (size > 0) out_.insert(out_.end(), first, first + size);
    }
    std::vector<std::uint8_t>& out_;
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
        std::vector<T> items(static_cast<std::size_t>(count));
        if (count > 0) std::memcpy(items.data(), take(items.size() * sizeof(T)).data(), items.size() * sizeof(T));
        return items;
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
