#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

// The fragments of transparent surfaces that fell in one strip of rows, kept whole until the
// strip resolves (doc/conventions.md#transparency): in chunks that never move, so that the
// colour a shader is yet to write keeps its address while later fragments are added.
namespace raster::detail {

struct Fragment {
    float depth;             // view depth, compared with the opaque samples' as they are
    float alpha;             // 0..1
    std::uint32_t pixel;     // y * width + x in the frame
    std::uint16_t samples;   // the samples it covers and is in front of (bit 0 alone at one sample)
    std::uint8_t colour[3];  // sRGB, as the shader wrote it
};

// The most memory a frame's fragments may take; a strip may hold its share by pixels.
constexpr std::size_t kMaxFragmentBytes = std::size_t{1} << 30;

class FragmentList {
public:
    // `cap`: the most fragments this strip keeps; one more is refused with std::length_error.
    explicit FragmentList(std::size_t cap = 0) noexcept : cap_(cap) {}

    Fragment& add(float depth, float alpha, std::uint32_t pixel, std::uint16_t samples) {
        if (size_ >= cap_ || size_ % kChunk == 0) grow();  // refused past the cap, else a new chunk made ready
        Fragment& added = chunks_[size_ / kChunk][size_ % kChunk];
        ++size_;
        if (const std::size_t local = pixel - first_pixel_; local < counts_)
            ++starts[local + 1];  // the resolve's count
        added = {depth, alpha, pixel, samples, {0, 0, 0}};
        return added;
    }
    [[nodiscard]] std::size_t size() const noexcept { return size_; }
    [[nodiscard]] bool empty() const noexcept { return size_ == 0; }
    [[nodiscard]] Fragment& operator[](std::size_t i) noexcept { return chunks_[i / kChunk][i % kChunk]; }
    // Calls f(fragment) for each, in drawing order, a chunk at a time.
    template <typename F>
    void for_each(F&& f) const {
        for (std::size_t begin = 0; begin < size_; begin += kChunk) {
            const Fragment* chunk = chunks_[begin / kChunk].get();
            const std::size_t n = std::min(kChunk, size_ - begin);
            for (std::size_t i = 0; i < n; ++i) f(chunk[i]);
        }
    }
    // Forgets the fragments, keeping their memory (and the resolve's) for the next frame.
    void clear() noexcept { size_ = 0; }
    // The same with a new cap and the strip's pixels [first_pixel, first_pixel + pixels), counted as they come:
    // a Renderer's lists, kept from frame to frame, take each frame's share.
    void clear(std::size_t cap, std::uint32_t first_pixel, std::size_t pixels) {
        size_ = 0, cap_ = cap, first_pixel_ = first_pixel, counts_ = pixels;
        starts.assign(pixels + 1, 0);
    }

    // The resolve's working memory, kept with the list so that a frame reuses the last one's pages.
    std::vector<Fragment> grouped;
    std::vector<std::uint32_t> starts;  // after clear(cap, ...): starts[p + 1] counts the fragments of local pixel p

private:
    [[gnu::noinline]] void grow() {
        if (size_ >= cap_) refuse();
        if (size_ % kChunk == 0 && size_ / kChunk == chunks_.size())
            chunks_.push_back(std::make_unique_for_overwrite<Fragment[]>(kChunk));  // each written before it is read
    }
    [[noreturn, gnu::cold, gnu::noinline]] static void refuse() {
        throw std::length_error("the transparent surfaces of this frame overlap in more than " +
                                std::to_string(kMaxFragmentBytes >> 20) +
                                " MiB of fragments; draw it smaller or with fewer samples");
    }

    static constexpr std::size_t kChunk = 4096;
    std::size_t cap_;
    std::size_t size_ = 0;
    std::uint32_t first_pixel_ = 0;
    std::size_t counts_ = 0;  // the pixels counted in starts, none unless clear(cap, ...) said
    std::vector<std::unique_ptr<Fragment[]>> chunks_;
};

}  // namespace raster::detail
