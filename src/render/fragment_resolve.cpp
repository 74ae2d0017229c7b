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
    if (list.empty()) return;
    // Grouped by pixel by the counts taken as the fragments came (drawing order kept), copied whole so that each
    // pixel's few lie together, then sorted by depth.
    const std::size_t first_pixel = static_cast<std::size_t>(y_begin) * width;
    std::vector<std::uint32_t>& starts = list.starts;
    const std::size_t strip_pixels = static_cast<std::size_t>(y_end - y_begin) * width;
    if (starts.size() != strip_pixels + 1) {  // not counted as they came: counted now
        starts.assign(strip_pixels + 1, 0);
        list.for_each([&](const Fragment& f) { ++starts[f.pixel - first_pixel + 1]; });
    }
    for (std::size_t i = 1; i < starts.size(); ++i) starts[i] += starts[i - 1];
    if (list.grouped.size() < list.size()) list.grouped.resize(list.size());
    Fragment* const grouped = list.grouped.data();
    std::uint32_t* const ends = starts.data();  // after the copy, each pixel's end
    list.for_each([&](const Fragment& f) { grouped[ends[f.pixel - first_pixel]++] = f; });
    const std::array<float, 256>& linear = linear_from_srgb_bytes();
    const int samples = opaque.samples != nullptr ? opaque.samples->samples() : 1;
    std::uint8_t* const pixels = frame.pixels();
    std::uint32_t begin = 0;
    for (std::size_t local = 0; local + 1 < starts.size(); begin = starts[local], ++local) {
        Fragment* const first = grouped + begin;
        Fragment* const last = grouped + starts[local];
        if (first == last) continue;
        // Far to near, equal depths in drawing order: insertion for the few a pixel mostly has.
        if (last - first > 32) {
            std::stable_sort(first, last, [](const Fragment& a, const Fragment& b) { return a.depth > b.depth; });
        } else {
            for (Fragment* i = first + 1; i != last; ++i) {
                const Fragment moved = *i;
                Fragment* j = i;
                for (; j != first && (j - 1)->depth < moved.depth; --j) *j = *(j - 1);
                *j = moved;
            }
        }
        const auto pixel = static_cast<std::uint32_t>(first_pixel + local);
        const int x = static_cast<int>(pixel % width), y = static_cast<int>(pixel / width);
        const std::uint8_t* colours = opaque.samples != nullptr ? opaque.samples->colours(x, y) : pixels + pixel * 3;
        const float* depths = opaque.samples != nullptr ? opaque.samples->depths(x, y)
                              : opaque.depth != nullptr ? opaque.depth->row(y) + x
                                                        : nullptr;
        // Fragments that each cover every sample composite the same way over samples that start alike: such a
        // sample takes the previous one's result, the same bits the same steps would give.
        const auto every = static_cast<std::uint16_t>((1U << static_cast<unsigned>(samples)) - 1U);
        const bool whole =
            samples > 1 && std::all_of(first, last, [&](const Fragment& f) { return f.samples == every; });
        float sum[4] = {0.0F, 0.0F, 0.0F, 0.0F};
        Composite sample{};
        const std::uint8_t* previous = nullptr;  // the last sample's opaque colour, null before the first
        bool previous_shown = false;
        for (int s = 0; s < samples; ++s) {
            const bool covered = depths == nullptr || !std::isinf(depths[s]);
            const bool shown = alpha == nullptr || covered;  // without alpha, the background is opaque too
            const std::uint8_t* start = colours + static_cast<std::size_t>(s) * 3;
            if (!(whole && previous != nullptr && shown == previous_shown &&
                  (!shown || std::equal(start, start + 3, previous)))) {
                sample = {{0.0F, 0.0F, 0.0F}, shown ? 1.0F : 0.0F};
                for (std::size_t c = 0; c < 3 && shown; ++c) sample.colour[c] = linear[start[c]];
                for (const Fragment* f = first; f != last; ++f) {
                    if ((f->samples & (1U << static_cast<unsigned>(s))) != 0) sample.over(*f, linear);
                }
            }
            previous = start, previous_shown = shown;
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
    list.clear();
    list.starts.clear();  // counted afresh next frame
}

}  // namespace raster::detail
