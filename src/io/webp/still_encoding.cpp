// Lossless still pictures: the whole frame as one picture, with or without alpha.
#include <raster/io/webp.hpp>

#include "io/webp/lossless_picture.hpp"
#include "io/webp/presets.hpp"

namespace raster {

std::vector<std::uint8_t> encode_webp_still(const Framebuffer& image, Effort effort,
                                            std::span<const std::uint8_t> alpha) {
    if (alpha.empty()) {
        return detail::encode_lossless(image.bytes().data(), image.width(), image.height(), image.width() * 3,
                                       detail::lossless_config(effort));
    }
    return detail::encode_lossless(rgba_bytes(image, alpha).data(), image.width(), image.height(), image.width() * 4,
                                   detail::lossless_config(effort), 4);
}

std::uintmax_t write_webp_still(const Framebuffer& image, const std::filesystem::path& path, Effort effort,
                                OutputPolicy policy) {
    check_output_path(path, policy);
    const std::vector<std::uint8_t> bytes = encode_webp_still(image, effort);
    write_output_file(path, bytes, policy);
    return bytes.size();
}

}  // namespace raster
