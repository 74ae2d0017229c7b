#include "render/fragment_resolve.hpp"

#include <raster/image/colour.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace raster::detail {

namespace {

// One sample's colour (premultiplied, linear) and alpha, its fragments composited over it.
struct Composite {
    float colour[3];
    float alpha;
    void over(const Fragment& fragment, const std::array<float, 256>& linear) noexcept {
        const float a = fragment.alpha, keep = 1.0F - a;
        for (std::size_t c = 0; c < 3; ++c) colour[c] = a * linear[fragment.colour[c]] + keep * colour[c];
        alpha = a + keep * alpha;
    }
};

}  // namespace

void resolve_fragments(FragmentList& list, OpaqueResult opaque, std::uint8_t* alpha, int y_begin, int y_end) {
    Framebuffer& frame = *opaque.frame;
    const auto width = static_cast<std::size_t>(frame.width());
    if (alpha != nullptr && opaque.samples == nullptr && opaque.depth != nullptr) {
        for (int y = y_begin; y < y_end; ++y) {
            const float* depths = opaque.depth->row(y);
            std::uint8_t* row = alpha + static_cast<std::size_t>(y) * width;
            for (std::size_t x = 0; x < width; ++x) row[x] = std::isinf(depths[x]) ? 0 : 255;
        }
    }
    std::deque<Fragment>& fragments = list.fragments();
    std::stable_sort(fragments.begin(), fragments.end(), [](const Fragment& a, const Fragment& b) {
        return a.pixel != b.pixel ? a.pixel < b.pixel : a.depth > b.depth;
    });
    const std::array<float, 256>& linear = linear_from_srgb_bytes();
    const int samples = opaque.samples != nullptr ? opaque.samples->samples() : 1;
    std::uint8_t* const pixels = frame.pixels();
    for (auto first = fragments.begin(); first != fragments.end();) {
        const std::uint32_t pixel = first->pixel;
        const auto last = std::find_if(first, fragments.end(), [&](const Fragment& f) { return f.pixel != pixel; });
        const int x = static_cast<int>(pixel % width), y = static_cast<int>(pixel / width);
        const std::uint8_t* colours = opaque.samples != nullptr ? opaque.samples->colours(x, y) : pixels + pixel * 3;
        const float* depths = opaque.samples != nullptr ? opaque.samples->depths(x, y)
                              : opaque.depth != nullptr ? opaque.depth->row(y) + x
                                                        : nullptr;
        float sum[4] = {0.0F, 0.0F, 0.0F, 0.0F};
        for (int s = 0; s < samples; ++s) {
            const bool covered = depths == nullptr || !std::isinf(depths[s]);
            const bool shown = alpha == nullptr || covered;  // without alpha, the background is opaque too
            Composite sample{{0.0F, 0.0F, 0.0F}, shown ? 1.0F : 0.0F};
            for (std::size_t c = 0; c < 3 && shown; ++c) sample.colour[c] = linear[colours[s * 3 + c]];
            for (auto f = first; f != last; ++f) {
                if ((f->samples & (1U << static_cast<unsigned>(s))) != 0) sample.over(*f, linear);
            }
            for (std::size_t c = 0; c < 3; ++c) sum[c] += sample.colour[c];
            sum[3] += sample.alpha;
        }
        std::uint8_t* out = pixels + static_cast<std::size_t>(pixel) * 3;
        const float share = 1.0F / static_cast<float>(samples);
        if (alpha == nullptr) {
            for (std::size_t c = 0; c < 3; ++c) out[c] = srgb_byte_from_linear(sum[c] * share);
        } else {
            // The surfaces' colour apart from the background: un-premultiplied by their alpha.
            const float unmix = sum[3] > 0.0F ? 1.0F / sum[3] : 0.0F;
            if (sum[3] > 0.0F) {
                for (std::size_t c = 0; c < 3; ++c) out[c] = srgb_byte_from_linear(sum[c] * unmix);
            }
            alpha[pixel] = static_cast<std::uint8_t>(std::lround(255.0F * sum[3] * share));
        }
        first = last;
    }
    fragments.clear();
}

}  // namespace raster::detail
