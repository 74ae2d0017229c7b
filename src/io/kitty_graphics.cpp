#include <raster/io/kitty_graphics.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace raster {
namespace {

constexpr std::string_view kApcStart = "\x1b_G";
constexpr std::string_view kStringEnd = "\x1b\\";

// "i=31,p=2" -> 31 for key 'i'; nullopt when the key is missing or not a number.
std::optional<std::uint32_t> key_value(std::string_view keys, char key) {
    while (!keys.empty()) {
        const std::size_t comma = keys.find(',');
        const std::string_view pair = keys.substr(0, comma);
        if (pair.size() > 2 && pair[0] == key && pair[1] == '=') {
            std::uint32_t value = 0;
            const auto [end, error] = std::from_chars(pair.data() + 2, pair.data() + pair.size(), value);
            if (error == std::errc() && end == pair.data() + pair.size()) return value;
            return std::nullopt;
        }
        if (comma == std::string_view::npos) break;
        keys.remove_prefix(comma + 1);
    }
    return std::nullopt;
}

// The length of a primary Device Attributes reply (ESC [ ? digits and ; ... c) at the start of
// `text`; 0 when there is none there (yet).
std::size_t device_attributes_length(std::string_view text) {
    if (!text.starts_with("\x1b[?")) return 0;
    for (std::size_t i = 3; i < text.size(); ++i) {
        if (text[i] == 'c') return i + 1;
        if (!((text[i] >= '0' && text[i] <= '9') || text[i] == ';')) return 0;
    }
    return 0;
}

}  // namespace

std::string base64(std::span<const std::uint8_t> bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t left = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t group = std::uint32_t{bytes[i]} << 16;
        if (left > 1) group |= std::uint32_t{bytes[i + 1]} << 8;
        if (left > 2) group |= bytes[i + 2];
        text += kAlphabet[(group >> 18) & 63];
        text += kAlphabet[(group >> 12) & 63];
        text += left > 1 ? kAlphabet[(group >> 6) & 63] : '=';
        text += left > 2 ? kAlphabet[group & 63] : '=';
    }
    return text;
}

std::optional<TerminalCells> display_cells(int width, int height, const TerminalWindow& window) {
    if (width <= 0 || height <= 0 || window.columns <= 0 || window.rows <= 0 || window.width_px <= 0 ||
        window.height_px <= 0) {
        return std::nullopt;
    }
    const double cell_width = static_cast<double>(window.width_px) / window.columns;
    const double cell_height = static_cast<double>(window.height_px) / window.rows;
    const int rows_free = std::max(1, window.rows - kKittySpareRows);
    const double scale = std::min(window.width_px / static_cast<double>(width), rows_free * cell_height / height);
    if (scale >= 1.0) return std::nullopt;
    // The side that meets the window's edge comes out whole; the other is rounded to its nearest cell.
    const int columns = std::clamp(static_cast<int>(std::lround(width * scale / cell_width)), 1, window.columns);
    const int rows = std::clamp(static_cast<int>(std::lround(height * scale / cell_height)), 1, rows_free);
    return TerminalCells{columns, rows};
}

std::string kitty_display(std::span<const std::uint8_t> png, std::optional<TerminalCells> cells) {
    const std::string payload = base64(png);
    std::string first = "a=T,f=100,q=2";
    if (cells) first += ",c=" + std::to_string(cells->columns) + ",r=" + std::to_string(cells->rows);
    std::string sequence;
    sequence.reserve(payload.size() + (payload.size() / kKittyChunkBytes + 1) * 32);
    std::size_t offset = 0;
    do {
        const std::size_t length = std::min(kKittyChunkBytes, payload.size() - offset);
        const bool last = offset + length == payload.size();
        sequence += kApcStart;
        if (offset == 0) sequence += first + ",";
        sequence += last ? "m=0;" : "m=1;";
        sequence.append(payload, offset, length);
        sequence += kStringEnd;
        offset += length;
    } while (offset < payload.size());
    return sequence;
}

std::string kitty_query(std::uint32_t id) {
    // AAAA: one black pixel, three bytes of RGB (f=24) sent directly (t=d).
    return std::string(kApcStart) + "i=" + std::to_string(id) + ",s=1,v=1,a=q,t=d,f=24;AAAA" + std::string(kStringEnd) +
           "\x1b[c";
}

KittyAnswer read_kitty_answer(std::string_view answer, std::uint32_t id) {
    KittyAnswer graphics = KittyAnswer::unsupported;  // what the Device Attributes reply will settle
    std::size_t at = 0;
    while (at < answer.size()) {
        const std::string_view rest = answer.substr(at);
        if (rest.starts_with(kApcStart)) {
            const std::size_t end = rest.find(kStringEnd);
            if (end == std::string_view::npos) return KittyAnswer::incomplete;
            const std::string_view body = rest.substr(kApcStart.size(), end - kApcStart.size());
            const std::size_t semicolon = body.find(';');
            if (semicolon != std::string_view::npos && key_value(body.substr(0, semicolon), 'i') == id) {
                graphics = body.substr(semicolon + 1) == "OK" ? KittyAnswer::supported : KittyAnswer::refused;
            }
            at += end + kStringEnd.size();
        } else if (const std::size_t length = device_attributes_length(rest); length > 0) {
            return graphics;
        } else {
            ++at;
        }
    }
    return KittyAnswer::incomplete;
}

}  // namespace raster
