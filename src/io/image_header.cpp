// Every format's reader shares the bounds-checked reads at the top; stays whole so none escapes.
// Reads image headers without any decoder: every read is bounds-checked and every walk advances
// through the data, so hostile files cost at most one pass over their bytes.
#include "io/image_header.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace raster::detail {
namespace {

using Bytes = std::span<const std::uint8_t>;

constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1A\n";

// Whether n bytes starting at `at` lie inside the data; written so that at + n cannot overflow.
bool fits(Bytes bytes, std::size_t at, std::uint64_t n) { return at <= bytes.size() && n <= bytes.size() - at; }

// Whether the data holds `magic` at `at` (false when the data ends first).
bool has_at(Bytes bytes, std::size_t at, std::string_view magic) {
    return fits(bytes, at, magic.size()) &&
           std::equal(magic.begin(), magic.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at),
                      [](char m, std::uint8_t b) { return static_cast<std::uint8_t>(m) == b; });
}

// Fixed-width reads; callers check with fits() first.
std::uint32_t be16(Bytes b, std::size_t at) { return std::uint32_t{b[at]} << 8 | b[at + 1]; }
std::uint32_t le16(Bytes b, std::size_t at) { return std::uint32_t{b[at + 1]} << 8 | b[at]; }
std::uint32_t le24(Bytes b, std::size_t at) { return std::uint32_t{b[at + 2]} << 16 | le16(b, at); }
std::uint32_t be32(Bytes b, std::size_t at) { return be16(b, at) << 16 | be16(b, at + 2); }
std::uint32_t le32(Bytes b, std::size_t at) { return le16(b, at + 2) << 16 | le16(b, at); }

std::string header_of(ImageFormat format) { return "the " + std::string(format_name(format)) + " header"; }

[[noreturn]] void cut_short(ImageFormat format) { throw std::runtime_error(header_of(format) + " is cut short"); }

[[noreturn]] void broken(ImageFormat format, const std::string& why) {
    throw std::runtime_error(header_of(format) + " is broken: " + why);
}

// Sizes arrive as 64-bit values so that every format's fields (unsigned 32-bit, signed, 24-bit)
// are checked against int's range before narrowing.
ImageHeader sized(ImageFormat format, std::int64_t width, std::int64_t height, bool truncated) {
    constexpr std::int64_t kMax = std::numeric_limits<int>::max();
    if (width < 1 || height < 1 || width > kMax || height > kMax) {
        throw std::runtime_error(header_of(format) + " gives a size of " + std::to_string(width) + "x" +
                                 std::to_string(height));
    }
    return {format, static_cast<int>(width), static_cast<int>(height), truncated};
}

// Formats stb_image would decode but raster does not read, named so that users know what they have.
std::string_view foreign_format(Bytes bytes) {
    if (has_at(bytes, 0, "GIF8")) return "a GIF image";
    if (has_at(bytes, 0, "8BPS")) return "a Photoshop (PSD) image";
    if (has_at(bytes, 0, "#?RADIANCE") || has_at(bytes, 0, "#?RGBE")) return "a Radiance HDR (RGBE) image";
    if (has_at(bytes, 0, "\x53\x80\xF6\x34")) return "a Softimage PIC image";
    const auto space = [](std::uint8_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    if (bytes.size() >= 3 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7' && space(bytes[2])) {
        return "a PNM (PBM, PGM or PPM) image";
    }
    return {};
}

// TGA has no signature: a header is plausible when its fields take values stb_image accepts.
bool plausible_tga(Bytes bytes) {
    if (bytes.size() < 18) return false;
    const int map = bytes[1], type = bytes[2], depth = bytes[16];
    const bool mapped = type == 1 || type == 9;
    const bool known_type = mapped || type == 2 || type == 3 || type == 10 || type == 11;
    const bool known_depth = depth == 8 || depth == 15 || depth == 16 || depth == 24 || depth == 32;
    return known_type && known_depth && map == (mapped ? 1 : 0);
}

// The info header sizes of the BMP versions in use: OS/2 core (12), Windows 3 to 5, OS/2 2.
bool known_bmp_info_size(std::uint32_t size) {
    return size == 12 || size == 40 || size == 52 || size == 56 || size == 64 || size == 108 || size == 124;
}

bool begins_like_webp(Bytes bytes) { return has_at(bytes, 0, "RIFF") && has_at(bytes, 8, "WEBP"); }

ImageHeader read_png(Bytes bytes) {
    // The IHDR chunk comes first; its width and height end at byte 24.
    if (!fits(bytes, 0, 24)) cut_short(ImageFormat::png);
    if (!has_at(bytes, 12, "IHDR") || be32(bytes, 8) != 13) broken(ImageFormat::png, "it does not start with IHDR");
    const std::int64_t width = be32(bytes, 16), height = be32(bytes, 20);
    // Chunks are length, type, data and CRC; the file is whole once IEND fits in it.
    for (std::size_t at = 8; fits(bytes, at, 12);) {
        const std::uint64_t chunk = 12 + std::uint64_t{be32(bytes, at)};
        if (!fits(bytes, at, chunk)) break;
        if (has_at(bytes, at + 4, "IEND")) return sized(ImageFormat::png, width, height, false);
        at += static_cast<std::size_t>(chunk);
    }
    return sized(ImageFormat::png, width, height, true);
}

// The frame headers SOF0..SOF15; C4 (Huffman tables), C8 (reserved) and CC (arithmetic conditioning) are not.
bool is_frame_marker(int marker) {
    return marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
}

// Where the next marker's FF byte is, from `at` on, or the data's size when none is left. Skips what
// may come between markers: entropy-coded data with its stuffed zeros (FF 00) and restart markers
// (FF D0..D7), fill bytes (FF FF), and stray bytes after a segment, which decoders tolerate.
std::size_t next_marker(Bytes bytes, std::size_t at) {
    for (; at + 1 < bytes.size(); ++at) {
        const int code = bytes[at + 1];
        if (bytes[at] == 0xFF && code != 0x00 && code != 0xFF && (code < 0xD0 || code > 0xD7)) return at;
    }
    return bytes.size();
}

ImageHeader read_jpeg(Bytes bytes) {
    std::int64_t width = 0, height = 0;
    bool have_size = false, truncated = true;
    // Segment by segment from after SOI; a progressive file has several scans (SOS), each followed by data.
    for (std::size_t at = next_marker(bytes, 2); at < bytes.size();) {
        const int marker = bytes[at + 1];
        at += 2;
        if (marker == 0xD9) {
            truncated = false;
            break;
        }
        if (marker == 0x01 || marker == 0xD8) {  // TEM and SOI carry no length
            at = next_marker(bytes, at);
            continue;
        }
        if (!fits(bytes, at, 2)) break;
        const std::uint32_t length = be16(bytes, at);  // counts its own two bytes
        if (length < 2) broken(ImageFormat::jpeg, "a segment is shorter than its length field");
        if (is_frame_marker(marker) && !have_size) {
            if (length < 8) broken(ImageFormat::jpeg, "the frame header is too short");
            if (!fits(bytes, at, 7)) break;
            height = be16(bytes, at + 3);
            width = be16(bytes, at + 5);
            have_size = true;
        }
        if (!fits(bytes, at, length)) break;
        at = next_marker(bytes, at + length);
    }
    if (!have_size) {
        if (truncated) cut_short(ImageFormat::jpeg);
        broken(ImageFormat::jpeg, "it has no frame header (SOF)");
    }
    return sized(ImageFormat::jpeg, width, height, truncated);
}

ImageHeader read_tga(Bytes bytes) {
    const std::uint64_t width = le16(bytes, 12), height = le16(bytes, 14);
    const std::uint64_t pixel_bytes = (bytes[16] + 7U) / 8U;  // 15-bit pixels take two bytes
    // stb_image skips the colour map's first-entry index as bytes before the map: count them too.
    const std::uint64_t map_bytes = bytes[1] == 1 ? le16(bytes, 3) + le16(bytes, 5) * ((bytes[7] + 7U) / 8U) : 0;
    const std::uint64_t start = 18 + bytes[0] + map_bytes;  // after the image ID and the colour map
    const std::uint64_t pixels = width * height;
    const auto header = [&](bool truncated) {
        return sized(ImageFormat::tga, static_cast<std::int64_t>(width), static_cast<std::int64_t>(height), truncated);
    };
    if (bytes[2] < 9) return header(!fits(bytes, 0, start + pixels * pixel_bytes));
    if (!fits(bytes, 0, start)) return header(true);
    // RLE packets: a count byte, then one pixel to repeat or that many literal pixels. Each packet takes
    // at least two bytes, so the walk ends within the data however large the claimed size.
    auto at = static_cast<std::size_t>(start);
    for (std::uint64_t done = 0; done < pixels;) {
        if (!fits(bytes, at, 1)) return header(true);
        const std::uint64_t count = (bytes[at] & 0x7FU) + 1U;
        const std::uint64_t packet = 1 + ((bytes[at] & 0x80U) != 0 ? 1 : count) * pixel_bytes;
        if (!fits(bytes, at, packet)) return header(true);
        at += static_cast<std::size_t>(packet);
        done += count;
    }
    return header(false);
}

ImageHeader read_bmp(Bytes bytes) {
    if (!fits(bytes, 0, 18)) cut_short(ImageFormat::bmp);
    const std::uint32_t info_size = le32(bytes, 14);
    if (!known_bmp_info_size(info_size))
        broken(ImageFormat::bmp, "unknown info header size " + std::to_string(info_size));
    const bool core = info_size == 12;  // OS/2 core header: 16-bit unsigned sides, never compressed
    if (!fits(bytes, 0, core ? 26 : 34)) cut_short(ImageFormat::bmp);
    // Windows headers hold signed 32-bit sides; converted before the conditional, which would make them unsigned.
    const auto side = [&](std::size_t core_at, std::size_t at) -> std::int64_t {
        return core ? std::int64_t{le16(bytes, core_at)} : std::int64_t{static_cast<std::int32_t>(le32(bytes, at))};
    };
    const std::int64_t width = side(18, 18), height = side(20, 22);
    const std::uint32_t bits = le16(bytes, core ? 24 : 28);
    const std::uint32_t compression = core ? 0 : le32(bytes, 30);
    if (compression == 1 || compression == 2)
        throw std::runtime_error("a compressed BMP (RLE); raster reads uncompressed BMP");
    if (compression != 0 && compression != 3) {
        throw std::runtime_error("a compressed BMP (method " + std::to_string(compression) +
                                 "); raster reads uncompressed BMP");
    }
    if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32) {
        throw std::runtime_error(header_of(ImageFormat::bmp) + " gives " + std::to_string(bits) + " bits per pixel");
    }
    const ImageHeader header = sized(ImageFormat::bmp, width, std::abs(height), true);  // negative: rows top-down
    // Rows are padded to 4 bytes; dividing rather than multiplying keeps huge sizes from overflowing.
    const std::uint64_t stride = (static_cast<std::uint64_t>(header.width) * bits + 31) / 32 * 4;
    const std::uint64_t offset = le32(bytes, 10);
    const bool whole =
        fits(bytes, 0, offset) && (bytes.size() - offset) / stride >= static_cast<std::uint64_t>(header.height);
    return {header.format, header.width, header.height, !whole};
}

ImageHeader read_webp(Bytes bytes) {
    if (!fits(bytes, 0, 20)) cut_short(ImageFormat::webp);  // RIFF header and the first chunk's type and size
    std::int64_t width = 0, height = 0;
    if (has_at(bytes, 12, "VP8 ")) {  // lossy: frame tag, start code 9D 01 2A, then 14-bit sides
        if (!fits(bytes, 20, 10)) cut_short(ImageFormat::webp);
        if (!has_at(bytes, 23, "\x9D\x01\x2A")) broken(ImageFormat::webp, "the VP8 start code is missing");
        width = le16(bytes, 26) & 0x3FFF;
        height = le16(bytes, 28) & 0x3FFF;
    } else if (has_at(bytes, 12, "VP8L")) {  // lossless: signature 2F, then width - 1 and height - 1 in 14 bits
        if (!fits(bytes, 20, 5)) cut_short(ImageFormat::webp);
        if (bytes[20] != 0x2F) broken(ImageFormat::webp, "the VP8L signature is missing");
        const std::uint32_t sides = le32(bytes, 21);
        width = (sides & 0x3FFF) + 1;
        height = (sides >> 14 & 0x3FFF) + 1;
    } else if (has_at(bytes, 12, "VP8X")) {  // extended: flags, 3 reserved bytes, canvas sides - 1 in 24 bits
        if (!fits(bytes, 20, 10)) cut_short(ImageFormat::webp);
        width = le24(bytes, 24) + std::int64_t{1};
        height = le24(bytes, 27) + std::int64_t{1};
    } else {
        broken(ImageFormat::webp, "the first chunk is not VP8, VP8L or VP8X");
    }
    // Whole when the RIFF size fits in the data and so does every chunk inside the RIFF.
    const std::uint64_t riff_end = 8 + std::uint64_t{le32(bytes, 4)};
    bool truncated = !fits(bytes, 0, riff_end);
    const Bytes riff = truncated ? bytes : bytes.first(static_cast<std::size_t>(riff_end));
    for (std::size_t at = 12; !truncated && fits(riff, at, 8);) {
        const std::uint64_t size = le32(riff, at + 4);
        truncated = !fits(riff, at + 8, size);
        at += static_cast<std::size_t>(8 + size + (size & 1));  // chunks are padded to an even size
    }
    return sized(ImageFormat::webp, width, height, truncated);
}

}  // namespace

std::string_view format_name(ImageFormat format) {
    switch (format) {
    case ImageFormat::png: return "PNG";
    case ImageFormat::jpeg: return "JPEG";
    case ImageFormat::tga: return "TGA";
    case ImageFormat::bmp: return "BMP";
    case ImageFormat::webp: return "WebP";
    }
    throw std::invalid_argument("unknown image format");
}

bool begins_like_image(std::span<const std::uint8_t> head) {
    const bool bmp = has_at(head, 0, "BM") && fits(head, 0, 18) && known_bmp_info_size(le32(head, 14));
    return has_at(head, 0, kPngSignature) || has_at(head, 0, "\xFF\xD8\xFF") || bmp || begins_like_webp(head) ||
           plausible_tga(head);
}

ImageHeader read_image_header(std::span<const std::uint8_t> bytes) {
    if (has_at(bytes, 0, kPngSignature)) return read_png(bytes);
    if (has_at(bytes, 0, "\xFF\xD8")) return read_jpeg(bytes);
    if (has_at(bytes, 0, "BM")) return read_bmp(bytes);
    if (begins_like_webp(bytes)) return read_webp(bytes);
    if (const std::string_view name = foreign_format(bytes); !name.empty()) {
        throw std::runtime_error(std::string(name) + "; raster reads PNG, JPEG, TGA, BMP and WebP");
    }
    if (plausible_tga(bytes)) return read_tga(bytes);  // last: TGA is recognised by plausibility alone
    throw std::runtime_error("not a PNG, JPEG, TGA, BMP or WebP image");
}

}  // namespace raster::detail
