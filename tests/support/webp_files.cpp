#include "support/webp_files.hpp"

#include <raster/io/webp.hpp>

#include <algorithm>
#include <stdexcept>

namespace test_support {
namespace {

void put(std::vector<std::uint8_t>& out, std::uint32_t value, int bytes) {
    for (int k = 0; k < bytes; ++k) out.push_back(static_cast<std::uint8_t>(value >> (8 * k)));
}

}  // namespace

std::vector<std::uint8_t> vp8l_chunk(int width, int height) {
    raster::Framebuffer image(width, height);
    image.clear({40, 90, 200});
    return vp8l_chunk(image);
}

std::vector<std::uint8_t> vp8l_chunk(const raster::Framebuffer& image, const std::vector<std::uint8_t>& alpha) {
    const std::vector<std::uint8_t> still = raster::encode_webp_still(image, raster::Effort::fast, alpha);
    // A simple lossless file is RIFF, size, WEBP, then the one VP8L chunk.
    if (still.size() < 20 || std::string(still.begin() + 12, still.begin() + 16) != "VP8L")
        throw std::logic_error("not a simple VP8L still");
    return {still.begin() + 12, still.end()};
}

std::vector<std::uint8_t> riff_chunk(const std::string& tag, const std::vector<std::uint8_t>& payload) {
    std::vector<std::uint8_t> chunk(tag.begin(), tag.end());
    put(chunk, static_cast<std::uint32_t>(payload.size()), 4);
    chunk.insert(chunk.end(), payload.begin(), payload.end());
    if (payload.size() % 2 == 1) chunk.push_back(0);
    return chunk;
}

std::vector<std::uint8_t> animated_webp(int canvas_width, int canvas_height, const std::vector<HandFrame>& frames,
                                        const std::vector<std::uint8_t>& extra) {
    std::vector<std::uint8_t> vp8x{2, 0, 0, 0};  // the animation flag
    put(vp8x, static_cast<std::uint32_t>(canvas_width - 1), 3);
    put(vp8x, static_cast<std::uint32_t>(canvas_height - 1), 3);
    std::vector<std::uint8_t> body = riff_chunk("VP8X", vp8x);
    std::vector<std::uint8_t> anim;
    put(anim, 0xFF000000U, 4);
    put(anim, 0, 2);
    const std::vector<std::uint8_t> anim_chunk = riff_chunk("ANIM", anim);
    body.insert(body.end(), anim_chunk.begin(), anim_chunk.end());
    for (const HandFrame& frame : frames) {
        std::vector<std::uint8_t> anmf;
        put(anmf, static_cast<std::uint32_t>(frame.x / 2), 3);
        put(anmf, static_cast<std::uint32_t>(frame.y / 2), 3);
        put(anmf, static_cast<std::uint32_t>(frame.width - 1), 3);
        put(anmf, static_cast<std::uint32_t>(frame.height - 1), 3);
        put(anmf, static_cast<std::uint32_t>(frame.duration_ms), 3);
        anmf.push_back(frame.flags);
        anmf.insert(anmf.end(), frame.picture.begin(), frame.picture.end());
        const std::vector<std::uint8_t> chunk = riff_chunk("ANMF", anmf);
        body.insert(body.end(), chunk.begin(), chunk.end());
    }
    body.insert(body.end(), extra.begin(), extra.end());
    std::vector<std::uint8_t> file{'R', 'I', 'F', 'F'};
    put(file, static_cast<std::uint32_t>(body.size() + 4), 4);
    for (const char c : std::string("WEBP")) file.push_back(static_cast<std::uint8_t>(c));
    file.insert(file.end(), body.begin(), body.end());
    return file;
}

std::size_t find_tag(const std::vector<std::uint8_t>& bytes, const std::string& tag, int n) {
    auto at = bytes.begin();
    for (int seen = 0;; ++seen, ++at) {
        at = std::search(at, bytes.end(), tag.begin(), tag.end());
        if (at == bytes.end() || seen == n) return static_cast<std::size_t>(at - bytes.begin());
    }
}

}  // namespace test_support
