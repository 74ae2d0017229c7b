#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <span>
#include <vector>

// The passes of one anti-aliased frame, one per sample position, summed in linear light and
// resolved to sRGB bytes (doc/conventions.md#samples).
namespace raster::detail {

class SampleResolve {
public:
    // `with_alpha`: each pass comes with its coverage (255 drawn, 0 not, between: the alpha of
    // transparent surfaces, weighting the pass's colour), and the resolve keeps
    // the colour of the surfaces apart from the share of samples they cover.
    SampleResolve(int width, int height, bool with_alpha);
    void add(const Framebuffer& pass, std::span<const std::uint8_t> coverage = {});
    // The mean of the passes. With alpha, each pixel is the mean of the passes that covered it
    // (`background` where none did) and `alpha` the share of passes that did, 0..255.
    void resolve(Framebuffer& out, Rgb background, std::vector<std::uint8_t>* alpha) const;

private:
    int width_;
    int height_;
    bool with_alpha_;
    int passes_ = 0;
    std::vector<float> sums_;     // three per pixel
    std::vector<float> covered_;  // the passes' coverage, each 0..1
};

}  // namespace raster::detail
