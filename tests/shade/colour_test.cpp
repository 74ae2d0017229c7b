#include <raster/image/colour.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <gtest/gtest.h>

using raster::LinearRgb;
using raster::Rgb;

namespace {

// The definition itself, in double: round(255 * encode(v)) with halves up, clamped.
int exact_byte(float v) {
    if (!(v > 0.0F)) return 0;
    if (v >= 1.0F) return 255;
    return static_cast<int>(std::floor(255.0 * raster::srgb_from_linear_channel(v) + 0.5));
}

std::uint8_t encode(float v) { return raster::srgb_from_linear({v, v, v}).r; }

}  // namespace

TEST(Colour, EveryByteSurvivesTheRoundTripThroughLinearLight) {
    for (int c = 0; c < 256; ++c) {
        const auto byte = static_cast<std::uint8_t>(c);
        const Rgb colour{byte, static_cast<std::uint8_t>(255 - c), byte};
        EXPECT_EQ(raster::srgb_from_linear(raster::linear_from_srgb(colour)), colour) << c;
    }
}

TEST(Colour, BlackAndWhiteAreFixedPointsAndTheKneeFollowsTheStandard) {
    EXPECT_EQ(raster::linear_from_srgb({0, 0, 0}), (LinearRgb{0, 0, 0}));
    EXPECT_EQ(raster::linear_from_srgb({255, 255, 255}), (LinearRgb{1, 1, 1}));
    EXPECT_EQ(raster::srgb_from_linear({0, 0, 0}), (Rgb{0, 0, 0}));
    EXPECT_EQ(raster::srgb_from_linear({1, 1, 1}), (Rgb{255, 255, 255}));
    EXPECT_DOUBLE_EQ(raster::linear_from_srgb_channel(0.04045), 0.04045 / 12.92);  // the linear segment
    EXPECT_DOUBLE_EQ(raster::linear_from_srgb_channel(0.5), std::pow(0.555 / 1.055, 2.4));
    EXPECT_DOUBLE_EQ(raster::srgb_from_linear_channel(0.0031308), 12.92 * 0.0031308);
    EXPECT_NEAR(raster::linear_from_srgb_channel(raster::srgb_from_linear_channel(0.2)), 0.2, 1e-15);
}

TEST(Colour, OutOfRangeAndNaNClampAtTheByteWrite) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(raster::srgb_from_linear({2.5F, -0.1F, nan}), (Rgb{255, 0, 0}));
    EXPECT_EQ(raster::srgb_from_linear({inf, -inf, 1e-30F}), (Rgb{255, 0, 0}));
    // Light adds and scales in linear space, and only the write clamps.
    const LinearRgb sum = raster::linear_from_srgb({200, 100, 50}) * 3.0F + LinearRgb{0.1F, 0.1F, 0.1F};
    EXPECT_GT(sum.r, 1.0F);
    EXPECT_EQ(raster::srgb_from_linear(sum).r, 255);
}

// Every 509th float in [0, 1] (and every one near each decision threshold) encodes to exactly
// the byte the standard's formula gives in double precision; the lab checks all of them.
TEST(Colour, EncodingMatchesTheDefinitionOnEveryFloatSampled) {
    const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0F);
    for (std::uint32_t bits = 0; bits <= one; bits += 509) {
        const float v = std::bit_cast<float>(bits);
        ASSERT_EQ(encode(v), exact_byte(v)) << v;
    }
    for (int b = 1; b < 256; ++b) {
        const auto boundary = static_cast<float>(raster::linear_from_srgb_channel((b - 0.5) / 255.0));
        float v = boundary;
        for (int k = 0; k < 8; ++k) v = std::nextafter(v, 0.0F);
        for (int k = 0; k < 16; ++k, v = std::nextafter(v, 1.0F)) ASSERT_EQ(encode(v), exact_byte(v)) << b << ": " << v;
    }
}
