#include "render/fragment_resolve.hpp"

#include <raster/image/colour.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

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
    FragmentList& fragments = list;
    if (fragments.empty()) return;
    // Grouped by pixel in one counting pass (drawing order kept), then each pixel's few sorted by depth.
    const std::size_t first_pixel = static_cast<std::size_t>(y_begin) * width;
    std::vector<std::uint32_t> starts(static_cast<std::size_t>(y_end - y_begin) * width + 1, 0);
    for (std::size_t i = 0; i < fragments.size(); ++i) ++starts[fragments[i].pixel - first_pixel + 1];
    for (std::size_t i = 1; i < starts.size(); ++i) starts[i] += starts[i - 1];
    std::vector<std::uint32_t> order(fragments.size());
    {
        std::vector<std::uint32_t> next(starts.begin(), starts.end() - 1);
        for (std::size_t i = 0; i < fragments.size(); ++i)
            order[next[fragments[i].pixel - first_pixel]++] = static_cast<std::uint32_t>(i);
    }
    const std::array<float, 256>& linear = linear_from_srgb_bytes();
    const int samples = opaque.samples != nullptr ? opaque.samples->samples() : 1;
    std::uint8_t* const pixels = frame.pixels();
    for (std::size_t local = 0; local + 1 < starts.size(); ++local) {
        const auto first = order.begin() + starts[local], last = order.begin() + starts[local + 1];
        if (first == last) continue;
        // Far to near, equal depths in drawing order: insertion for the few a pixel mostly has.
        const auto farther = [&](std::uint32_t a, std::uint32_t b) { return fragments[a].depth > fragments[b].depth; };
        if (last - first > 32) std::stable_sort(first, last, farther);
        for (auto i = first + 1; i != last && last - first <= 32; ++i) {
            const std::uint32_t moved = *i;
            auto j = i;
            for (; j != first && fragments[*(j - 1)].depth < fragments[moved].depth; --j) *j = *(j - 1);
            *j = moved;
        }
        const auto pixel = static_cast<std::uint32_t>(first_pixel + local);
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
            for (std::size_t c = 0; c < 3 && shown; ++c)
                sample.colour[c] = linear[colours[static_cast<std::size_t>(s) * 3 + c]];
            for (auto f = first; f != last; ++f) {
                const Fragment& fragment = fragments[*f];
                if ((fragment.samples & (1U << static_cast<unsigned>(s))) != 0) sample.over(fragment, linear);
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
    }
    fragments.clear();
}

}  // namespace raster::detail
