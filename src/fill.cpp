#include <raster/fill.hpp>

#include <algorithm>
#include <cstdlib>
#include <array>

namespace raster {
namespace {

// floor(n / d) for d > 0.
std::int64_t floor_div(std::int64_t n, std::int64_t d) {
    const std::int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

// The first and last pixel whose centre lies in [low, high] (subpixel units); an arithmetic
// shift is a floor division by kSubpixelOne.
std::int64_t first_pixel_at_or_after(std::int64_t low) { return -((-low) >> kSubpixelBits); }
std::int64_t last_pixel_at_or_before(std::int64_t high) { return high >> kSubpixelBits; }

// E(i, j) = step_x * i + step_y * j + offset at pixel (i, j), oriented so the inside is E >= bias;
// bias is 1 on edges that are neither top nor left, so samples exactly on them stay outside.
struct EdgeFunction {
    std::int64_t step_x;
    std::int64_t step_y;
    std::int64_t offset;
    std::int64_t bias;

    static EdgeFunction through(SubpixelPoint a, SubpixelPoint b) {
        const std::int64_t ex = std::int64_t{b.x} - a.x;
        const std::int64_t ey = std::int64_t{b.y} - a.y;
        // The inward normal is (-ey, ex): a left edge has it pointing right, a top edge down.
        const bool top_left = ey < 0 || (ey == 0 && ex > 0);
        return {-ey * kSubpixelOne, ex * kSubpixelOne, ey * a.x - ex * a.y, top_left ? 0 : 1};
    }
};

// One edge's limit on the span of successive rows. The limit is floor(numerator / divisor); it is
// kept as quotient and remainder, so after one division at the first row each row costs two
// additions and stays exact.
class EdgeWalker {
public:
    enum class Kind { left, right, row };  // limits the first column, the last, or the whole row

    EdgeWalker() = default;
    // With `stepping` off the walker serves one row only and skips the second division.
    EdgeWalker(const EdgeFunction& edge, std::int64_t row, bool stepping) {
        // Inside means step_x * i >= need(row), and need falls by step_y from row to row.
        const std::int64_t need = edge.bias - (edge.step_y * row + edge.offset);
        std::int64_t numerator = need;
        std::int64_t change = -edge.step_y;
        if (edge.step_x > 0) {  // first column: ceil(need / step_x)
            kind_ = Kind::left;
            divisor_ = edge.step_x;
            numerator += divisor_ - 1;
        } else if (edge.step_x < 0) {  // last column: floor(-need / -step_x)
            kind_ = Kind::right;
            divisor_ = -edge.step_x;
            numerator = -need;
            change = edge.step_y;
        } else {  // a horizontal edge admits the whole row while need <= 0
            kind_ = Kind::row;
            divisor_ = 1;
        }
        quotient_ = floor_div(numerator, divisor_);
        remainder_ = numerator - quotient_ * divisor_;
        if (!stepping) return;
        quotient_step_ = floor_div(change, divisor_);
        remainder_step_ = change - quotient_step_ * divisor_;
    }

    void clamp(std::int64_t& first, std::int64_t& last) const {
        switch (kind_) {
        case Kind::left: first = std::max(first, quotient_); break;
        case Kind::right: last = std::min(last, quotient_); break;
        case Kind::row: if (quotient_ > 0) last = first - 1; break;
        }
    }

    void next_row() {
        quotient_ += quotient_step_;
        remainder_ += remainder_step_;
        if (remainder_ >= divisor_) {
            remainder_ -= divisor_;
            ++quotient_;
        }
    }

private:
    Kind kind_ = Kind::row;
    std::int64_t divisor_ = 1;
    std::int64_t quotient_ = 0;
    std::int64_t remainder_ = 0;
    std::int64_t quotient_step_ = 0;
    std::int64_t remainder_step_ = 0;
};

constexpr std::size_t kMaxCorners = 8;

}  // namespace

std::int64_t twice_signed_area(std::span<const SubpixelPoint> corners) noexcept {
    std::int64_t sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const SubpixelPoint a = corners[i];
        const SubpixelPoint b = corners[(i + 1) % corners.size()];
        sum += std::int64_t{a.x} * b.y - std::int64_t{b.x} * a.y;
    }
    return sum;
}

std::int64_t rasterize_convex(std::span<const SubpixelPoint> corners, PixelRect clip, SpanVisitor visit) {
    const std::size_t count = corners.size();
    if (count < 3 || count > kMaxCorners) return 0;
    constexpr std::int64_t limit = std::int64_t{kMaxSubpixelCoordinate} * kSubpixelOne;
    std::int64_t min_x = corners[0].x, max_x = corners[0].x, min_y = corners[0].y, max_y = corners[0].y;
    for (const SubpixelPoint c : corners) {
        if (std::abs(std::int64_t{c.x}) > limit || std::abs(std::int64_t{c.y}) > limit) return 0;
        min_x = std::min<std::int64_t>(min_x, c.x), max_x = std::max<std::int64_t>(max_x, c.x);
        min_y = std::min<std::int64_t>(min_y, c.y), max_y = std::max<std::int64_t>(max_y, c.y);
    }
    // Cheap rejections first: no pixel centre of the clip inside the bounding box.
    const std::int64_t first_row = std::max<std::int64_t>(first_pixel_at_or_after(min_y), clip.y);
    const std::int64_t last_row =
        std::min<std::int64_t>(last_pixel_at_or_before(max_y), std::int64_t{clip.y} + clip.height - 1);
    if (first_row > last_row || first_pixel_at_or_after(min_x) >= std::int64_t{clip.x} + clip.width ||
        last_pixel_at_or_before(max_x) < clip.x) {
        return 0;
    }
    const std::int64_t area = twice_signed_area(corners);
    if (area == 0) return 0;

    std::array<EdgeWalker, kMaxCorners> walkers{};
    const bool several_rows = last_row > first_row;
    for (std::size_t i = 0; i < count; ++i) {
        SubpixelPoint a = corners[i];
        SubpixelPoint b = corners[(i + 1) % count];
        if (area < 0) std::swap(a, b);  // walk every polygon in the same rotational sense
        walkers[i] = EdgeWalker(EdgeFunction::through(a, b), first_row, several_rows);
    }
    for (std::int64_t row = first_row; row <= last_row; ++row) {
        std::int64_t first = clip.x;
        std::int64_t last = std::int64_t{clip.x} + clip.width - 1;
        for (std::size_t i = 0; i < count; ++i) {
            walkers[i].clamp(first, last);
            walkers[i].next_row();
        }
        if (first <= last) visit({static_cast<int>(row), static_cast<int>(first), static_cast<int>(last + 1)});
    }
    return last_row - first_row + 1;
}

std::int64_t fill_convex(Framebuffer& framebuffer, std::span<const SubpixelPoint> corners,
                         Rgb colour, glm::ivec2 origin) {
    const PixelRect clip{origin.x, origin.y, framebuffer.width(), framebuffer.height()};
    return rasterize_convex(corners, clip, [&](Span span) {
        framebuffer.fill_row(span.y - origin.y, span.x_begin - origin.x, span.x_end - origin.x, colour);
    });
}

}  // namespace raster
