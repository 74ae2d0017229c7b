#include "finished_picture.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <span>
#include <vector>

bool is_nonempty_regular_file(const std::filesystem::path& path) {
    // A link, a directory or an empty file named like the picture is not one a run wrote.
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::symlink_status(path, error);
    if (error || status.type() != std::filesystem::file_type::regular) return false;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    return !error && size > 0;
}

bool holds_finished_picture(const std::filesystem::path& path, ImageFormat format) {
    if (!is_nonempty_regular_file(path)) return false;
    try {
        if (format == ImageFormat::webp) {
            raster::for_each_webp_frame(path, [](const raster::DecodedFrame&) { return true; });
            return true;
        }
        const auto is_png = [](std::span<const std::uint8_t> head) {
            static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
            return head.size() >= 8 && std::equal(head.begin(), head.begin() + 8, kSignature);
        };
        const std::vector<std::uint8_t> bytes = raster::read_input_file(
            path, raster::InputRules{"picture", std::uintmax_t{1} << 30, is_png, 8, "a PNG file", {}});
        (void)raster::decode_png(bytes, static_cast<std::size_t>(raster::kMaxImageSide) * raster::kMaxImageSide);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}
