#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

// The tests' own reading of Kitty graphics escape sequences, written apart from the library's.
namespace test_support {

struct KittyChunk {
    std::map<std::string, std::string> keys;  // "a" -> "T", "m" -> "1", ...
    std::string payload;                      // base64, as sent
};

// The ESC _ G keys ; payload ESC \ sequences in `text` from the first whose keys start with
// `first` (a=T: the display, not the query), back to back, up to the one with m=0. Fails the test
// (and returns what it read) when there is none or one is left open.
std::vector<KittyChunk> kitty_chunks(std::string_view text, std::string_view first = "a=T");

// RFC 4648 base64 with padding; an ill-formed text fails the test.
std::vector<std::uint8_t> from_base64(std::string_view text);

}  // namespace test_support
