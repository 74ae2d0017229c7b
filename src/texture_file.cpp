// The only file that includes stb_image.
#include <raster/texture_file.hpp>

#include <raster/webp.hpp>

#include <algorithm>
#include <fstream>
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

// Whether bytes begin like one of stb_image's formats that raster does not read (PSD, HDR, PIC,
// PNM, GIF): stb_image is not hardened against hostile files, so only the documented formats
// reach it.
bool unsupported_format(std::span<const std::uint8_t> bytes) {
    const auto starts = [&](std::string_view magic) {
        return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin(), [](char m, std::uint8_t b) {
                   return static_cast<std::uint8_t>(m) == b;
               });
    };
    return starts("8BPS") || starts("#?RADIANCE") || starts("#?RGBE") || starts("\x53\x80\xF6\x34") || starts("GIF8") ||
           (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7');
}

Framebuffer decode_with_stb(std::span<const std::uint8_t> bytes, std::size_t max_texels) {
    if (unsupported_format(bytes)) throw std::runtime_error("a PSD, HDR, PIC, PNM or GIF image; raster reads PNG, JPEG, TGA, BMP and WebP");
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) throw std::runtime_error("image file too large");
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (stbi_info_from_memory(data, length, &width, &height, &channels) == 0) {
        throw std::runtime_error("not an image raster can read (PNG, JPEG, TGA, BMP or WebP)");
    }
    const auto texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (width < 1 || height < 1 || texels > max_texels || width > kMaxImageSide || height > kMaxImageSide) {
        throw std::runtime_error("image is " + std::to_string(width) + "x" + std::to_string(height) + ", more than the " +
                                 std::to_string(max_texels) + " texels allowed");
    }
    const std::unique_ptr<stbi_uc, void (*)(void*)> rgb(stbi_load_from_memory(data, length, &width, &height, &channels, 3),
                                                         stbi_image_free);
    if (!rgb) {
        const char* reason = stbi_failure_reason();
        throw std::runtime_error(std::string("cannot decode image: ") + (reason != nullptr ? reason : "unknown reason"));
    }
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
    return {width, height, std::vector<std::uint8_t>(rgb.get(), rgb.get() + size)};
}

std::vector<std::uint8_t> read_image_file(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw std::runtime_error("is a directory, not an image");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw std::runtime_error("cannot read: " + error.message());
    if (size > kMaxTextureFileBytes) throw std::runtime_error("file is larger than " + std::to_string(kMaxTextureFileBytes >> 20) + " MiB");
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()))) {
        throw std::runtime_error("cannot read the file");
    }
    return bytes;
}

}  // namespace

Texture decode_texture(std::span<const std::uint8_t> bytes, std::size_t max_texels) {
    if (looks_like_webp(bytes)) return Texture(decode_webp_still(bytes, max_texels));
    return Texture(decode_with_stb(bytes, max_texels));
}

Texture read_texture(const std::filesystem::path& path, std::size_t max_texels) {
    try {
        return decode_texture(read_image_file(path), max_texels);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(path.string() + ": " + error.what());
    }
}

}  // namespace raster
