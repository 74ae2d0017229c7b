#include <raster/io/frame_range.hpp>

#include <algorithm>
#include <charconv>

namespace raster {

std::optional<FrameRange> frame_range_from_text(std::string_view text) {
    const std::size_t dots = text.find(".."), colon = text.find(':');
    const std::size_t split = dots != std::string_view::npos ? dots : colon;
    if (split == std::string_view::npos) return std::nullopt;
    const std::size_t separator = dots != std::string_view::npos ? 2U : 1U;
    const std::string_view a = text.substr(0, split), b = text.substr(split + separator);
    const auto read = [](std::string_view digits, int& value) {
        if (digits.empty() || digits.size() > 9 ||
            !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            return false;
        return std::from_chars(digits.data(), digits.data() + digits.size(), value).ec == std::errc();
    };
    FrameRange range;
    if (!read(a, range.first) || !read(b, range.last) || range.first > range.last) return std::nullopt;
    return range;
}

}  // namespace raster
