// One table of encoded samples; stays whole so that every format's cases read side by side.
#include "io/image_header.hpp"

#include "support/encoded_images.hpp"

#include <gtest/gtest.h>
#include <webp/encode.h>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

using namespace std::string_view_literals;
using raster::detail::begins_like_image;
using raster::detail::format_name;
using raster::detail::ImageFormat;
using raster::detail::ImageHeader;
using raster::detail::read_image_header;

namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr int kWidth = 13;
constexpr int kHeight = 7;

// Pixels in runs of three, so that RLE encoders write both repeat and literal packets.
Bytes test_pixels(int channels) {
    Bytes pixels;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth * channels; ++x)
            pixels.push_back(static_cast<std::uint8_t>((x / (3 * channels)) * 40 + y * 7));
    }
    return pixels;
}

Bytes png() { return test_support::encode_png(test_pixels(3), kWidth, kHeight, 3); }

Bytes jpeg() { return test_support::encode_jpeg(test_pixels(3), kWidth, kHeight, 3); }

// Three channels give a 24-bit BI_RGB file; four a 32-bit BI_BITFIELDS one with a version 4 header.
Bytes bmp(int channels = 3) { return test_support::encode_bmp(test_pixels(channels), kWidth, kHeight, channels); }

Bytes tga(bool rle) { return test_support::encode_tga(test_pixels(3), kWidth, kHeight, 3, rle); }

Bytes webp(bool lossless) {
    std::uint8_t* encoded = nullptr;
    const Bytes pixels = test_pixels(3);
    const std::size_t size = lossless ? WebPEncodeLosslessRGB(pixels.data(), kWidth, kHeight, kWidth * 3, &encoded)
                                      : WebPEncodeRGB(pixels.data(), kWidth, kHeight, kWidth * 3, 80.0F, &encoded);
    Bytes out(encoded, encoded + size);
    WebPFree(encoded);
    return out;
}

void put_le32(Bytes& bytes, std::size_t at, std::uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) bytes[at + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

void put_be32(Bytes& bytes, std::size_t at, std::uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) bytes[at + i] = static_cast<std::uint8_t>(value >> (24 - 8 * i));
}

// A lossless WebP wrapped in the extended format: a VP8X chunk giving the canvas, then the VP8L chunk.
Bytes extended_webp() {
    const Bytes simple = webp(true);
    Bytes out = {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', 'X', 10, 0, 0, 0, 0, 0, 0, 0};
    for (const int side : {kWidth - 1, kHeight - 1}) {
        for (int i = 0; i < 3; ++i) out.push_back(static_cast<std::uint8_t>(side >> (8 * i)));
    }
    out.insert(out.end(), simple.begin() + 12, simple.end());
    put_le32(out, 4, static_cast<std::uint32_t>(out.size() - 8));
    return out;
}

// An 18-byte TGA header of the given type, 24 bits per pixel, no image ID and no colour map.
Bytes tga_header(std::uint8_t type, int width, int height) {
    return {0,
            0,
            type,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            0,
            static_cast<std::uint8_t>(width),
            static_cast<std::uint8_t>(width >> 8),
            static_cast<std::uint8_t>(height),
            static_cast<std::uint8_t>(height >> 8),
            24,
            0};
}

ImageHeader read(const Bytes& bytes) { return read_image_header(bytes); }

Bytes cut(const Bytes& bytes, std::size_t size) {
    return {bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size)};
}

// The reason read_image_header gives for rejecting the bytes, or "" when it reads them.
std::string rejection(const Bytes& bytes) {
    try {
        static_cast<void>(read(bytes));
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

// Where marker FF `code` first appears.
std::size_t find_marker(const Bytes& bytes, std::uint8_t code) {
    for (std::size_t i = 0; i + 1 < bytes.size(); ++i) {
        if (bytes[i] == 0xFF && bytes[i + 1] == code) return i;
    }
    ADD_FAILURE() << "no marker FF " << int{code};
    return bytes.size();
}

struct Sample {
    std::string name;
    Bytes bytes;
    ImageFormat format;
    int width = kWidth;
    int height = kHeight;
};

std::vector<Sample> samples() {
    return {{"PNG", png(), ImageFormat::png},
            {"JPEG", jpeg(), ImageFormat::jpeg},
            {"BMP 24-bit", bmp(3), ImageFormat::bmp},
            {"BMP 32-bit bitfields", bmp(4), ImageFormat::bmp},
            {"TGA", tga(false), ImageFormat::tga},
            {"TGA RLE", tga(true), ImageFormat::tga},
            {"WebP lossless", webp(true), ImageFormat::webp},
            {"WebP lossy", webp(false), ImageFormat::webp},
            {"WebP extended", extended_webp(), ImageFormat::webp}};
}

// A progressive JPEG's marker sequence made by hand: an APP1 segment holding FF D9, a SOF2 frame of
// 48x32, and three scans whose data holds a stuffed zero, a restart marker and fill bytes.
Bytes progressive_jpeg() {
    return {0xFF, 0xD8,                                                  // SOI
            0xFF, 0xE1, 0x00, 0x08, 'E',  'x',  0xFF, 0xD9, 0x00, 0x00,  // APP1 whose payload looks like EOI
            0xFF, 0xC2, 0x00, 0x0B, 0x08, 0x00, 0x20, 0x00, 0x30, 0x01, 0x01, 0x11, 0x00,  // SOF2
            0xFF, 0xC4, 0x00, 0x03, 0x00,                                                  // DHT
            0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x00, 0x00,                    // SOS: DC scan
            0x12, 0x34, 0xFF, 0x00, 0x56, 0xFF, 0xD3, 0x78,                                // data, stuffed zero, RST3
            0xFF, 0xFF, 0xC4, 0x00, 0x03, 0x10,                                            // fill byte, then DHT
            0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x01, 0x3F, 0x00,                    // SOS: AC scan
            0xAB, 0xFF, 0x00, 0xCD,                                                        // data
            0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x01, 0x3F, 0x10,                    // SOS: refinement scan
            0xEF, 0x01,                                                                    // data
            0xFF, 0xD9};                                                                   // EOI
}

}  // namespace

TEST(ImageHeader, ReadsFormatAndSizeOfWholeFiles) {
    for (const Sample& sample : samples()) {
        SCOPED_TRACE(sample.name);
        const ImageHeader header = read(sample.bytes);
        EXPECT_EQ(header.format, sample.format);
        EXPECT_EQ(header.width, sample.width);
        EXPECT_EQ(header.height, sample.height);
        EXPECT_FALSE(header.truncated);
    }
}

TEST(ImageHeader, CallsEveryCutOfAFileTruncatedOrRejectsIt) {
    for (const Sample& sample : samples()) {
        SCOPED_TRACE(sample.name);
        for (std::size_t size = 0; size < sample.bytes.size(); ++size) {
            const Bytes part = cut(sample.bytes, size);
            if (!rejection(part).empty()) continue;
            const ImageHeader header = read(part);
            EXPECT_TRUE(header.truncated) << "cut to " << size << " of " << sample.bytes.size() << " bytes";
            EXPECT_EQ(header.format, sample.format);
            EXPECT_EQ(header.width, sample.width);
            EXPECT_EQ(header.height, sample.height);
        }
    }
}

TEST(ImageHeader, CutsHalfWayBeforeTheEndAndAfterTheHeaderAreTruncated) {
    const Bytes png_file = png(), jpeg_file = jpeg(), bmp_file = bmp(), tga_file = tga(false), rle_file = tga(true);
    const Bytes webp_file = webp(true);
    const std::size_t after_sof = find_marker(jpeg_file, 0xC0) + 2 + jpeg_file[find_marker(jpeg_file, 0xC0) + 3];
    const std::vector<std::pair<const Bytes*, std::vector<std::size_t>>> cuts = {
        {&png_file, {png_file.size() / 2, png_file.size() - 12, png_file.size() - 1, 33}},  // 33: after IHDR
        {&jpeg_file, {jpeg_file.size() / 2, jpeg_file.size() - 2, jpeg_file.size() - 1, after_sof}},
        {&bmp_file, {bmp_file.size() / 2, bmp_file.size() - 1, 54}},  // 54: after both headers
        {&tga_file, {tga_file.size() / 2, tga_file.size() - 1, 18}},
        {&rle_file, {rle_file.size() / 2, rle_file.size() - 1, 18}},
        {&webp_file, {webp_file.size() / 2, webp_file.size() - 1, 25}},  // 25: after the VP8L sides
    };
    for (const auto& [file, sizes] : cuts) {
        for (const std::size_t size : sizes) {
            const ImageHeader header = read(cut(*file, size));
            EXPECT_TRUE(header.truncated) << format_name(header.format) << " cut to " << size;
            EXPECT_EQ(header.width, kWidth) << format_name(header.format) << " cut to " << size;
            EXPECT_EQ(header.height, kHeight) << format_name(header.format) << " cut to " << size;
        }
    }
}

TEST(ImageHeader, ThrowsForACutInsideTheHeader) {
    EXPECT_EQ(rejection(cut(png(), 20)), "the PNG header is cut short");
    EXPECT_EQ(rejection(cut(jpeg(), 12)), "the JPEG header is cut short");
    EXPECT_EQ(rejection(cut(bmp(), 16)), "the BMP header is cut short");
    EXPECT_EQ(rejection(cut(bmp(), 30)), "the BMP header is cut short");
    EXPECT_EQ(rejection(cut(webp(true), 22)), "the WebP header is cut short");
    EXPECT_EQ(rejection(cut(webp(false), 28)), "the WebP header is cut short");
    EXPECT_EQ(rejection(cut(tga(false), 17)), "not a PNG, JPEG, TGA, BMP or WebP image");  // TGA: no signature to go by
}

TEST(ImageHeader, TgaClaiming4000SquaredWithNoPixelsIsTruncated) {
    for (const std::uint8_t type : std::initializer_list<std::uint8_t>{2, 10}) {
        const ImageHeader header = read(tga_header(type, 4000, 4000));
        EXPECT_EQ(header.format, ImageFormat::tga);
        EXPECT_EQ(header.width, 4000);
        EXPECT_EQ(header.height, 4000);
        EXPECT_TRUE(header.truncated);
    }
    // 65535 x 65535 claimed, 4 MiB of run packets given: the walk ends with the data, not the pixel count.
    Bytes huge = tga_header(10, 65535, 65535);
    for (int i = 0; i < (1 << 20); ++i) huge.insert(huge.end(), {0xFF, 1, 2, 3});
    EXPECT_TRUE(read(huge).truncated);
}

TEST(ImageHeader, RleTgaIsWholeOnlyWhenItsPacketsCoverEveryPixel) {
    Bytes file = tga_header(10, 4, 2);
    file.insert(file.end(), {0x83, 9, 9, 9});                                // a run of four
    file.insert(file.end(), {0x03, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});  // four literal pixels
    EXPECT_FALSE(read(file).truncated);
    Bytes trailing = file;
    trailing.insert(trailing.end(), {0, 0, 0, 0});
    EXPECT_FALSE(read(trailing).truncated);
    EXPECT_TRUE(read(cut(file, file.size() - 1)).truncated);  // last literal pixel short
    EXPECT_TRUE(read(cut(file, 22)).truncated);               // second packet missing
    EXPECT_TRUE(read(cut(file, 20)).truncated);               // run pixel short
}

TEST(ImageHeader, ReadsThePngSizeOf65535SquaredFromAHeaderAlone) {
    Bytes header = cut(png(), 33);  // signature and IHDR chunk with its CRC
    put_be32(header, 16, 65535);
    put_be32(header, 20, 65535);
    const ImageHeader read_header = read(header);
    EXPECT_EQ(read_header.format, ImageFormat::png);
    EXPECT_EQ(read_header.width, 65535);
    EXPECT_EQ(read_header.height, 65535);
    EXPECT_TRUE(read_header.truncated);
}

TEST(ImageHeader, ThrowsForAZeroSide) {
    Bytes png_file = png();
    put_be32(png_file, 16, 0);
    EXPECT_EQ(rejection(png_file), "the PNG header gives a size of 0x7");
    Bytes jpeg_file = jpeg();
    const std::size_t sof = find_marker(jpeg_file, 0xC0);
    jpeg_file[sof + 5] = 0;
    jpeg_file[sof + 6] = 0;
    EXPECT_EQ(rejection(jpeg_file), "the JPEG header gives a size of 13x0");
    Bytes bmp_file = bmp();
    put_le32(bmp_file, 18, 0);
    EXPECT_EQ(rejection(bmp_file), "the BMP header gives a size of 0x7");
    EXPECT_EQ(rejection(tga_header(2, 10, 0)), "the TGA header gives a size of 10x0");
}

TEST(ImageHeader, ThrowsForSidesBeyondAnInt) {
    Bytes png_file = png();
    put_be32(png_file, 16, 0x80000000U);
    EXPECT_EQ(rejection(png_file), "the PNG header gives a size of 2147483648x7");
    Bytes bmp_file = bmp();
    put_le32(bmp_file, 22, 0x80000000U);  // INT32_MIN rows, top-down
    EXPECT_EQ(rejection(bmp_file), "the BMP header gives a size of 13x2147483648");
    put_le32(bmp_file, 18, 0xFFFFFFFFU);
    EXPECT_NE(rejection(bmp_file), "");
}

TEST(ImageHeader, ReadsATopDownBmpWithNegativeHeight) {
    Bytes file = bmp();
    put_le32(file, 22, static_cast<std::uint32_t>(-kHeight));
    const ImageHeader header = read(file);
    EXPECT_EQ(header.width, kWidth);
    EXPECT_EQ(header.height, kHeight);
    EXPECT_FALSE(header.truncated);
}

TEST(ImageHeader, RejectsCompressedBmp) {
    Bytes file = bmp();
    put_le32(file, 30, 1);  // BI_RLE8
    EXPECT_EQ(rejection(file), "a compressed BMP (RLE); raster reads uncompressed BMP");
    put_le32(file, 30, 4);  // BI_JPEG
    EXPECT_EQ(rejection(file), "a compressed BMP (method 4); raster reads uncompressed BMP");
}

TEST(ImageHeader, WebPWithAChunkReachingPastTheRiffIsTruncated) {
    Bytes file = webp(true);
    put_le32(file, 16, static_cast<std::uint32_t>(file.size()));  // the VP8L chunk claims more than the file holds
    EXPECT_TRUE(read(file).truncated);
}

TEST(ImageHeader, NamesImageFormatsItDoesNotRead) {
    const auto bytes = [](std::string_view text) { return Bytes(text.begin(), text.end()); };
    const std::string reads = "; raster reads PNG, JPEG, TGA, BMP and WebP";
    EXPECT_EQ(rejection(bytes("GIF89a\x0D\x00\x07\x00"sv)), "a GIF image" + reads);
    EXPECT_EQ(rejection(bytes("8BPS\x00\x01"sv)), "a Photoshop (PSD) image" + reads);
    EXPECT_EQ(rejection(bytes("P6\n13 7\n255\n")), "a PNM (PBM, PGM or PPM) image" + reads);
    EXPECT_EQ(rejection(bytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n")), "a Radiance HDR (RGBE) image" + reads);
    EXPECT_EQ(rejection(bytes("\x53\x80\xF6\x34PICT")), "a Softimage PIC image" + reads);
}

TEST(ImageHeader, RejectsGarbageAsNoImage) {
    const std::string_view text = "this is plainly not an image, just some text";
    for (const Bytes& garbage : {Bytes{}, Bytes{0xFF}, Bytes(text.begin(), text.end()), Bytes(100, 0)}) {
        EXPECT_EQ(rejection(garbage), "not a PNG, JPEG, TGA, BMP or WebP image");
    }
}

TEST(ImageHeader, AcceptsBytesAfterTheJpegEnd) {
    Bytes file = jpeg();
    file.insert(file.end(), {'t', 'r', 'a', 'i', 'l', 'e', 'r', 0xFF, 0xD8, 0xFF, 0xE0});
    const ImageHeader header = read(file);
    EXPECT_EQ(header.width, kWidth);
    EXPECT_EQ(header.height, kHeight);
    EXPECT_FALSE(header.truncated);
}

TEST(ImageHeader, WalksEveryScanOfAProgressiveJpeg) {
    const Bytes file = progressive_jpeg();
    const ImageHeader header = read(file);
    EXPECT_EQ(header.format, ImageFormat::jpeg);
    EXPECT_EQ(header.width, 48);
    EXPECT_EQ(header.height, 32);
    EXPECT_FALSE(header.truncated);
    // Cut inside the APP1 segment (before the frame header), then at every point after the frame header.
    EXPECT_EQ(rejection(cut(file, 10)), "the JPEG header is cut short");
    for (std::size_t size = 25; size < file.size(); ++size) {
        EXPECT_TRUE(read(cut(file, size)).truncated) << "cut to " << size;
    }
}

TEST(ImageHeader, BeginsLikeImageForTheFirstBytesOfEachFormat) {
    for (const Sample& sample : samples()) {
        EXPECT_TRUE(begins_like_image(cut(sample.bytes, 32))) << sample.name;
    }
    EXPECT_TRUE(begins_like_image(tga_header(2, 4000, 4000)));
    EXPECT_TRUE(begins_like_image(cut(progressive_jpeg(), 3)));
}

TEST(ImageHeader, DoesNotBeginLikeImageForOtherBytes) {
    const auto bytes = [](std::string_view text) { return Bytes(text.begin(), text.end()); };
    EXPECT_FALSE(begins_like_image(Bytes{}));
    EXPECT_FALSE(begins_like_image(bytes("GIF89a\x0D\x00\x07\x00"sv)));
    EXPECT_FALSE(begins_like_image(bytes("8BPS\x00\x01"sv)));
    EXPECT_FALSE(begins_like_image(bytes("this is plainly not an image, just some text")));
    EXPECT_FALSE(begins_like_image(Bytes(32, 0)));
    EXPECT_FALSE(begins_like_image(cut(png(), 4)));  // a signature cut short
    EXPECT_FALSE(begins_like_image(bytes("BM and then text")));
    Bytes mapped_without_map = tga_header(1, 4, 4);  // colour-mapped type but no colour map
    EXPECT_FALSE(begins_like_image(mapped_without_map));
}

TEST(ImageHeader, NamesFormatsAsUsersKnowThem) {
    EXPECT_EQ(format_name(ImageFormat::png), "PNG");
    EXPECT_EQ(format_name(ImageFormat::jpeg), "JPEG");
    EXPECT_EQ(format_name(ImageFormat::tga), "TGA");
    EXPECT_EQ(format_name(ImageFormat::bmp), "BMP");
    EXPECT_EQ(format_name(ImageFormat::webp), "WebP");
}
