// libFuzzer target: the product's fill and line must agree with the exact reference on any input,
// and must never crash or write outside their target.
#include "coverage.hpp"
#include "reference.hpp"

#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/line.hpp>

#include <cstdint>
#include <cstdlib>
#include <vector>
#include <fuzzer/FuzzedDataProvider.h>

namespace {

constexpr int kSide = 24;

void check_fill(FuzzedDataProvider& input) {
    const bool small = input.ConsumeBool();  // small coordinates meet at pixel centres often
    const int count = input.ConsumeIntegralInRange(3, 9);
    std::vector<raster::SubpixelPoint> corners;
    for (int i = 0; i < count; ++i) {
        const auto coordinate = [&] {
            return small ? input.ConsumeIntegralInRange<std::int32_t>(-8 * 256, (kSide + 8) * 256)
                         : input.ConsumeIntegral<std::int32_t>();
        };
        const std::int32_t x = coordinate();
        corners.push_back({x, coordinate()});
    }
    const raster::PixelRect clip{input.ConsumeIntegralInRange(-4, 4), input.ConsumeIntegralInRange(-4, 4), kSide,
                                 kSide};
    lab::Coverage actual(clip);
    raster::rasterize_convex(corners, clip, [&](raster::Span span) {
        if (span.y < clip.y || span.y >= clip.y + clip.height || span.x_begin < clip.x ||
            span.x_end > clip.x + clip.width || span.x_begin >= span.x_end) {
            std::abort();  // a span outside the clip, or empty
        }
        actual.hit_row(span.y, span.x_begin, span.x_end);
    });

    constexpr std::int64_t limit = std::int64_t{raster::kMaxSubpixelCoordinate} * raster::kSubpixelOne;
    bool in_range = count <= 8;
    std::vector<lab::ExactPoint> exact;
    for (const raster::SubpixelPoint c : corners) {
        in_range = in_range && std::abs(std::int64_t{c.x}) <= limit && std::abs(std::int64_t{c.y}) <= limit;
        exact.push_back({std::int64_t{c.x} << (lab::kExactBits - raster::kSubpixelBits),
                         std::int64_t{c.y} << (lab::kExactBits - raster::kSubpixelBits)});
    }
    lab::Coverage expected(clip);
    if (in_range) lab::reference_polygon(exact, expected);
    for (int y = clip.y; y < clip.y + clip.height; ++y) {
        for (int x = clip.x; x < clip.x + clip.width; ++x) {
            if (actual.at(x, y) != expected.at(x, y)) std::abort();
        }
    }
}

void check_line(FuzzedDataProvider& input) {
    const bool small = input.ConsumeBool();
    const auto coordinate = [&] {
        return small ? input.ConsumeIntegralInRange(-40, kSide + 40) : input.ConsumeIntegral<int>();
    };
    const glm::ivec2 from{coordinate(), coordinate()};
    const glm::ivec2 to{coordinate(), coordinate()};
    const glm::ivec2 origin{input.ConsumeIntegralInRange(-4, 4), input.ConsumeIntegralInRange(-4, 4)};
    raster::Framebuffer image(kSide, kSide);
    const std::int64_t walked = raster::draw_line(image, from, to, {255, 255, 255}, origin);
    if (walked < 0 || walked > 2 * kSide) std::abort();  // work bounded by the visible part

    const std::int64_t steps = std::max(std::abs(std::int64_t{to.x} - from.x), std::abs(std::int64_t{to.y} - from.y));
    if (steps > (1 << 16)) return;  // the reference walks every step
    lab::Coverage expected({origin.x, origin.y, kSide, kSide});
    lab::reference_line(from, to, expected);
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) {
            const bool lit = image.pixel(x, y) != raster::Rgb{};
            if (lit != (expected.at(x + origin.x, y + origin.y) != 0)) std::abort();
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider input(data, size);
    if (input.ConsumeBool())
        check_fill(input);
    else
        check_line(input);
    return 0;
}
