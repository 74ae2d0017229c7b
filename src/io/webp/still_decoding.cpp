// A still WebP held in memory, recognised by its first bytes and decoded to RGB.
#include <raster/io/webp.hpp>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <webp/decode.h>

namespace raster {

bool looks_like_webp(std::span<const std::uint8_t> bytes) noexcept {
    constexpr std::string_view riff = "RIFF", webp = "WEBP";
    const auto matches = [&](std::size_t at, std::string_view tag) {
        return bytes.size() >= at + tag.size() &&
               std::equal(tag.begin(), tag.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
    };
    return matches(0, riff) && matches(8, webp);
}

Framebuffer decode_webp_still(std::span<const std::uint8_t> bytes, std::size_t max_pixels) {
    WebPBitstreamFeatures features;
    if (WebPGetFeatures(bytes.data(), bytes.size(), &features) != VP8_STATUS_OK)
        throw std::runtime_error("not a WebP image");
    if (features.has_animation != 0) throw std::runtime_error("an animated WebP, not a still image");
    const auto pixels = static_cast<std::size_t>(features.width) * static_cast<std::size_t>(features.height);
    if (pixels > max_pixels) {
        throw std::runtime_error("image is " + std::to_string(features.width) + "x" + std::to_string(features.height) +
                                 ", more than the " + std::to_string(max_pixels) + " pixels allowed");
    }
    int width = 0, height = 0;
    const std::unique_ptr<std::uint8_t, void (*)(void*)> rgb(WebPDecodeRGB(bytes.data(), bytes.size(), &width, &height),
                                                             WebPFree);
    if (!rgb) throw std::runtime_error("corrupt WebP image data");
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    return {width, height, std::vector<std::uint8_t>(rgb.get(), rgb.get() + size)};
}

}  // namespace raster
