#include <raster/image/colour.hpp>
#include <raster/image/lanes.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace raster {
namespace {

// threshold[b] is the smallest float v that encodes to byte b or above: the linear value where
// 255 * encode(v) reaches b - 1/2, rounded up to a float (threshold[0] is 0). start[i] is the
// byte of i / kBuckets, where a search from it begins: a bucket spans at most two bytes.
struct Thresholds {
    static constexpr int kBuckets = 4096;
    std::array<float, 257> at{};  // at[256] = +infinity stops every search
    std::array<std::uint8_t, kBuckets> start{};

    Thresholds() noexcept {
        for (int b = 1; b < 256; ++b) {
            const double exact = linear_from_srgb_channel((b - 0.5) / 255.0);
            float up = static_cast<float>(exact);
            if (static_cast<double>(up) < exact) up = std::nextafter(up, 1.0F);
            at[static_cast<std::size_t>(b)] = up;
        }
        at[256] = std::numeric_limits<float>::infinity();
        std::uint8_t b = 0;
        for (int i = 0; i < kBuckets; ++i) {
            const float low = static_cast<float>(i) / kBuckets;
            while (at[static_cast<std::size_t>(b) + 1] <= low) ++b;
            start[static_cast<std::size_t>(i)] = b;
        }
    }
};

// Immutable after its first use, so it holds no state between calls.
const Thresholds& thresholds() noexcept {
    static const Thresholds table;
    return table;
}

std::uint8_t encode(float v, const Thresholds& table) noexcept {
    if (!(v > 0.0F)) return 0;  // negative, zero or NaN
    if (v >= 1.0F) return 255;
    // The bucket gives the byte of its lower end; the exact thresholds finish the job, so every
    // float gets exactly the byte its thresholds say. One step suffices for every float below 1
    // (checked over all of them): taken without a branch, which colours in no order (a point
    // cloud's) would mispredict; the loop after it never runs, so it is always predicted.
    std::size_t b = table.start[static_cast<std::size_t>(v * Thresholds::kBuckets)];
    b += table.at[b + 1] <= v ? 1U : 0U;
    while (table.at[b + 1] <= v) ++b;
    return static_cast<std::uint8_t>(b);
}

}  // namespace

double linear_from_srgb_channel(double encoded) noexcept {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

double srgb_from_linear_channel(double linear) noexcept {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

const std::array<float, 256>& linear_from_srgb_bytes() noexcept {
    // Immutable after its first use, like the encoding thresholds.
    static const std::array<float, 256> table = [] {
        std::array<float, 256> linear{};
        for (std::size_t b = 0; b < linear.size(); ++b)
            linear[b] = static_cast<float>(linear_from_srgb_channel(static_cast<double>(b) / 255.0));
        return linear;
    }();
    return table;
}

LinearRgb linear_from_srgb(Rgb colour) noexcept {
    const std::array<float, 256>& linear = linear_from_srgb_bytes();
    return {linear[colour.r], linear[colour.g], linear[colour.b]};
}

std::uint8_t srgb_byte_from_linear(float linear) noexcept { return encode(linear, thresholds()); }

Rgb srgb_from_linear(LinearRgb colour) noexcept {
    const Thresholds& table = thresholds();
    return {encode(colour.r, table), encode(colour.g, table), encode(colour.b, table)};
}

void srgb_from_linear(const LaneRgb& colours, std::span<Rgb> out) noexcept {
    const Thresholds& table = thresholds();
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = {encode(colours.r[i], table), encode(colours.g[i], table), encode(colours.b[i], table)};
    }
}

}  // namespace raster
