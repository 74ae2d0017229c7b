#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>

// The fragments of transparent surfaces that fell in one strip of rows, kept whole until the
// strip resolves (doc/conventions.md#transparency): a deque, so that the colour a shader is yet
// to write keeps its address while later fragments are added.
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
        if (fragments_.size() >= cap_) {
            throw std::length_error("the transparent surfaces of this frame overlap in more than " +
                                    std::to_string(kMaxFragmentBytes >> 20) +
                                    " MiB of fragments; draw it smaller or with fewer samples");
        }
        return fragments_.push_back({depth, alpha, pixel, samples, {0, 0, 0}}), fragments_.back();
    }
    [[nodiscard]] std::deque<Fragment>& fragments() noexcept { return fragments_; }

private:
    std::size_t cap_;
    std::deque<Fragment> fragments_;
};

}  // namespace raster::detail
