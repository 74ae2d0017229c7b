#include "kitty_sequence.hpp"

#include <gtest/gtest.h>

namespace test_support {

std::vector<KittyChunk> kitty_chunks(std::string_view text, std::string_view first) {
    std::vector<KittyChunk> chunks;
    std::size_t at = text.find(std::string("\x1b_G") + std::string(first));
    if (at == std::string_view::npos) {
        ADD_FAILURE() << "no ESC _ G" << first << " sequence";
        return chunks;
    }
    while (at < text.size() && text.substr(at).starts_with("\x1b_G")) {
        const std::size_t end = text.find("\x1b\\", at);
        if (end == std::string_view::npos) {
            ADD_FAILURE() << "a sequence left open at byte " << at;
            return chunks;
        }
        const std::string_view body = text.substr(at + 3, end - at - 3);
        const std::size_t semicolon = body.find(';');
        KittyChunk chunk;
        std::string_view keys = body.substr(0, semicolon);
        while (!keys.empty()) {
            const std::size_t comma = keys.find(',');
            const std::string_view pair = keys.substr(0, comma);
            const std::size_t equals = pair.find('=');
            EXPECT_NE(equals, std::string_view::npos) << pair;
            if (equals != std::string_view::npos)
                chunk.keys[std::string(pair.substr(0, equals))] = std::string(pair.substr(equals + 1));
            keys = comma == std::string_view::npos ? std::string_view() : keys.substr(comma + 1);
        }
        if (semicolon != std::string_view::npos) chunk.payload = std::string(body.substr(semicolon + 1));
        chunks.push_back(std::move(chunk));
        at = end + 2;
        if (chunks.back().keys["m"] == "0") break;
    }
    return chunks;
}

std::vector<std::uint8_t> from_base64(std::string_view text) {
    const auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    };
    std::vector<std::uint8_t> bytes;
    if (text.size() % 4 != 0) {
        ADD_FAILURE() << "base64 of " << text.size() << " characters, not a multiple of 4";
        return bytes;
    }
    for (std::size_t i = 0; i < text.size(); i += 4) {
        const bool last = i + 4 == text.size();
        const int pad = last ? (text[i + 3] == '=') + (text[i + 2] == '=') : 0;
        std::uint32_t group = 0;
        for (int k = 0; k < 4; ++k) {
            const int v = k >= 4 - pad ? 0 : value(text[i + static_cast<std::size_t>(k)]);
            if (v < 0) {
                ADD_FAILURE() << "not base64: '" << text[i + static_cast<std::size_t>(k)] << "' at "
                              << i + static_cast<std::size_t>(k);
                return bytes;
            }
            group = (group << 6) | static_cast<std::uint32_t>(v);
        }
        bytes.push_back(static_cast<std::uint8_t>(group >> 16));
        if (pad < 2) bytes.push_back(static_cast<std::uint8_t>(group >> 8));
        if (pad < 1) bytes.push_back(static_cast<std::uint8_t>(group));
    }
    return bytes;
}

}  // namespace test_support
