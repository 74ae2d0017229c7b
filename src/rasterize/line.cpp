#include <raster/rasterize/line.hpp>

#include <algorithm>
#include <cstdlib>

namespace raster {
namespace {

// 128-bit products keep the DDA exact for any pair of 32-bit endpoints.
__extension__ using Wide = __int128;

Wide floor_div(Wide numerator, Wide denominator) {
    Wide quotient = numerator / denominator;
    if (numerator % denominator != 0 && numerator < 0) --quotient;
    return quotient;
}

// The samples of one segment, described along its dominant (major) axis.
struct DdaWalk {
    std::int64_t major_start;
    std::int64_t major_step;  // +1 or -1
    std::int64_t minor_start;
    std::int64_t minor_delta;
    std::int64_t steps;  // N > 0

    std::int64_t major_at(std::int64_t i) const { return major_start + major_step * i; }
    // minor_start + round(minor_delta * i / N), halves rounded up, in exact integers.
    std::int64_t minor_at(std::int64_t i) const {
        return minor_start + static_cast<std::int64_t>(floor_div(Wide{2} * minor_delta * i + steps, Wide{2} * steps));
    }
};

// Smallest i in [lo, hi] where `holds` becomes true (it must be monotone); hi + 1 if never.
template <typename Predicate>
std::int64_t first_where(std::int64_t lo, std::int64_t hi, Predicate holds) {
    std::int64_t end = hi + 1;
    while (lo < end) {
        const std::int64_t mid = lo + (end - lo) / 2;
        if (holds(mid))
            end = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

struct SampleRange {
    std::int64_t first;
    std::int64_t last;
};

// Sample indices whose pixel lies inside [0, major_size) x [0, minor_size); empty if first > last.
SampleRange visible_samples(const DdaWalk& walk, std::int64_t major_size, std::int64_t minor_size) {
    SampleRange range{0, walk.steps};
    if (walk.major_step > 0) {
        range.first = std::max(range.first, -walk.major_start);
        range.last = std::min(range.last, major_size - 1 - walk.major_start);
    } else {
        range.first = std::max(range.first, walk.major_start - (major_size - 1));
        range.last = std::min(range.last, walk.major_start);
    }
    if (range.first > range.last) return range;

    const auto lo = range.first;
    const auto hi = range.last;
    if (walk.minor_delta >= 0) {
        range.first = first_where(lo, hi, [&](auto i) { return walk.minor_at(i) >= 0; });
        range.last = first_where(lo, hi, [&](auto i) { return walk.minor_at(i) >= minor_size; }) - 1;
    } else {
        range.first = first_where(lo, hi, [&](auto i) { return walk.minor_at(i) < minor_size; });
        range.last = first_where(lo, hi, [&](auto i) { return walk.minor_at(i) < 0; }) - 1;
    }
    return range;
}

}  // namespace

std::int64_t draw_line(Framebuffer& framebuffer, glm::ivec2 from, glm::ivec2 to, Rgb colour, glm::ivec2 origin) {
    // Shifting both ends by whole pixels shifts every sample alike, so work relative to origin.
    const std::int64_t x0 = std::int64_t{from.x} - origin.x;
    const std::int64_t y0 = std::int64_t{from.y} - origin.y;
    const std::int64_t dx = std::int64_t{to.x} - from.x;
    const std::int64_t dy = std::int64_t{to.y} - from.y;
    const bool x_major = std::abs(dx) >= std::abs(dy);
    const std::int64_t steps = std::max(std::abs(dx), std::abs(dy));
    const auto inside = [&](std::int64_t x, std::int64_t y) {
        return x >= 0 && y >= 0 && x < framebuffer.width() && y < framebuffer.height();
    };
    if (steps == 0) {
        if (!inside(x0, y0)) return 0;
        framebuffer.set_pixel(static_cast<int>(x0), static_cast<int>(y0), colour);
        return 1;
    }

    const DdaWalk walk =
        x_major ? DdaWalk{x0, dx > 0 ? 1 : -1, y0, dy, steps} : DdaWalk{y0, dy > 0 ? 1 : -1, x0, dx, steps};
    const std::int64_t major_size = x_major ? framebuffer.width() : framebuffer.height();
    const std::int64_t minor_size = x_major ? framebuffer.height() : framebuffer.width();
    // With both ends inside, every sample is visible and the search can be skipped.
    const SampleRange range = inside(x0, y0) && inside(x0 + dx, y0 + dy)
                                  ? SampleRange{0, steps}
                                  : visible_samples(walk, major_size, minor_size);
    if (range.first > range.last) return 0;

    // Step the minor coordinate as quotient + remainder of (2 * delta * i + N) / 2N; at i = 0 they
    // are minor_start and N, so most lines need no 128-bit division.
    const std::int64_t denominator = 2 * steps;
    std::int64_t first_minor = walk.minor_start;
    std::int64_t first_remainder = steps;
    if (range.first > 0) {
        first_minor = walk.minor_at(range.first);
        first_remainder = static_cast<std::int64_t>(Wide{2} * walk.minor_delta * range.first + steps -
                                                    Wide{first_minor - walk.minor_start} * denominator);
    }
    const auto step_through = [&](auto plot) {
        std::int64_t major = walk.major_at(range.first);
        std::int64_t minor = first_minor;
        std::int64_t remainder = first_remainder;
        for (std::int64_t i = range.first; i <= range.last; ++i) {
            plot(static_cast<int>(major), static_cast<int>(minor));
            major += walk.major_step;
            remainder += 2 * walk.minor_delta;
            if (remainder >= denominator) {
                remainder -= denominator;
                ++minor;
            } else if (remainder < 0) {
                remainder += denominator;
                --minor;
            }
        }
    };
    if (x_major)
        step_through([&](int x, int y) { framebuffer.set_pixel(x, y, colour); });
    else
        step_through([&](int y, int x) { framebuffer.set_pixel(x, y, colour); });
    return range.last - range.first + 1;
}

}  // namespace raster
