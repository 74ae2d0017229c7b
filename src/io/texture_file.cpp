// The only file that includes stb_image.
#include <raster/io/texture_file.hpp>

#include <raster/io/input_file.hpp>
#include <raster/io/webp.hpp>

#include "io/image_header.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>
#include <stb_image.h>

namespace raster {

namespace {

// stb_image for the formats it shares with raster's header reader, which has already checked the
// size and that the data is whole: stb_image is not hardened against hostile files. An image
// with alpha keeps it beside its colour.
Texture decode_with_stb(std::span<const std::uint8_t> bytes, std::string_view format) {
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("image file too large");
    int width = 0, height = 0, channels = 0;
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    const bool with_alpha =
        stbi_info_from_memory(data, length, &width, &height, &channels) != 0 && (channels == 2 || channels == 4);
    const int kept = with_alpha ? 4 : 3;
    const std::unique_ptr<stbi_uc, void (*)(void*)> texels(
        stbi_load_from_memory(data, length, &width, &height, &channels, kept), stbi_image_free);
    if (!texels) throw std::runtime_error("the " + std::string(format) + " data is corrupt");
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (!with_alpha)
        return Texture(Framebuffer(width, height, std::vector<std::uint8_t>(texels.get(), texels.get() + count * 3)));
    std::vector<std::uint8_t> rgb(count * 3), alpha(count);
    for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = texels.get()[i * 4 + c];
        alpha[i] = texels.get()[i * 4 + 3];
    }
    return Texture(Framebuffer(width, height, std::move(rgb)), std::move(alpha));
}

}  // namespace

Texture decode_texture(std::span<const std::uint8_t> bytes, std::size_t max_texels) {
    const detail::ImageHeader header = detail::read_image_header(bytes);
    const std::string_view format = detail::format_name(header.format);
    const auto texels = static_cast<std::size_t>(header.width) * static_cast<std::size_t>(header.height);
    if (texels > max_texels || header.width > kMaxImageSide || header.height > kMaxImageSide) {
        throw std::runtime_error("image is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                                 ", more than the " + std::to_string(max_texels) + " texels allowed");
    }
    if (header.truncated)
        throw std::runtime_error("truncated image: the " + std::string(format) + " data ends before the picture does");
    if (header.format == detail::ImageFormat::webp) return Texture(decode_webp_still(bytes, max_texels));
    return decode_with_stb(bytes, format);
}

Texture read_texture(const std::filesystem::path& path, std::size_t max_texels, const std::filesystem::path& confine,
                     std::vector<InputRecord>* sources) {
    try {
        InputRules rules;
        rules.role = "texture";
        rules.max_bytes = kMaxTextureFileBytes;
        rules.signature = detail::begins_like_image;
        rules.signature_bytes = 32;
        rules.expected = "a PNG, JPEG, TGA, BMP or WebP image";
        rules.confine = confine;
        return decode_texture(read_input_file(path, rules, sources), max_texels);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(printable(path.string()) + ": " + error.what());
    }
}

}  // namespace raster
