#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

// The Kitty terminal graphics protocol (sw.kovidgoyal.net/kitty/graphics-protocol), which Kitty,
// WezTerm, Ghostty and Konsole speak, as pure functions: what to send to show a PNG inline, how
// large to show it, and how to read the terminal's answer to the support query. The terminal's
// own input and output are the caller's (apps/terminal_preview.cpp).
namespace raster {

// Base64 bytes in one escape sequence at most: the protocol's limit for a chunk.
inline constexpr std::size_t kKittyChunkBytes = 4096;
// Rows left below a picture scaled to the window: the report line and the shell's prompt.
inline constexpr int kKittySpareRows = 2;

// A window as TIOCGWINSZ reports it; a size the terminal does not know is 0.
struct TerminalWindow {
    int columns = 0;
    int rows = 0;
    int width_px = 0;
    int height_px = 0;
};

// The cells a picture is shown across (the c= and r= keys), each at least 1.
struct TerminalCells {
    int columns = 1;
    int rows = 1;
    friend bool operator==(const TerminalCells&, const TerminalCells&) = default;
};

// The cells that show a width x height picture as large as fits across the window and in all
// but its last kKittySpareRows rows, keeping its aspect to within a cell; nullopt shows it at its
// own size, which is what happens when it already fits or the window's pixel size is unknown.
[[nodiscard]] std::optional<TerminalCells> display_cells(int width, int height, const TerminalWindow& window);

// Escape sequences that transmit the PNG bytes and display them at the cursor (a=T, f=100,
// no replies: q=2), in base64 chunks of at most kKittyChunkBytes (m=1 on all but the last, m=0
// on it), scaled into `cells` when given.
[[nodiscard]] std::string kitty_display(std::span<const std::uint8_t> png, std::optional<TerminalCells> cells);

// The support query: a 1x1 RGB picture queried (a=q) under `id`, then a primary Device
// Attributes request, which every terminal answers, so silence is not the only "no".
[[nodiscard]] std::string kitty_query(std::uint32_t id);

// What the terminal has sent back so far to kitty_query(id).
enum class KittyAnswer {
    incomplete,   // no Device Attributes reply yet: keep reading, or give up at the timeout
    supported,    // "OK" for `id` before the Device Attributes reply
    unsupported,  // the Device Attributes reply with no graphics reply before it
    refused,      // an error reply for `id` (such as ENOTSUPPORTED) before the Device Attributes reply
};
// Reads the terminal's answer; anything else in it (keys typed meanwhile) is skipped.
[[nodiscard]] KittyAnswer read_kitty_answer(std::string_view answer, std::uint32_t id);

// Standard base64 (RFC 4648) with padding, as the protocol carries payloads.
[[nodiscard]] std::string base64(std::span<const std::uint8_t> bytes);

}  // namespace raster
