#include "picture.hpp"

#include <algorithm>
#include <sstream>

namespace test_support {
namespace {

char symbol_for(raster::Rgb colour, const std::map<char, raster::Rgb>& legend) {
    if (colour == raster::Rgb{}) return '.';
    const auto entry =
        std::find_if(legend.begin(), legend.end(), [colour](const auto& item) { return item.second == colour; });
    return entry == legend.end() ? '+' : entry->first;
}

std::vector<std::string> rows_of(const raster::Framebuffer& image, const std::map<char, raster::Rgb>& legend) {
    std::vector<std::string> rows;
    for (int y = 0; y < image.height(); ++y) {
        std::string row;
        for (int x = 0; x < image.width(); ++x) row += symbol_for(image.pixel(x, y), legend);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

std::string to_ascii_art(const raster::Framebuffer& image, const std::map<char, raster::Rgb>& legend) {
    std::string art;
    for (const std::string& row : rows_of(image, legend)) art += row + '\n';
    return art;
}

::testing::AssertionResult looks_like(const raster::Framebuffer& image, const std::vector<std::string>& rows,
                                      const std::map<char, raster::Rgb>& legend) {
    const std::vector<std::string> actual = rows_of(image, legend);
    if (actual == rows) return ::testing::AssertionSuccess();

    std::ostringstream message;
    message << "pictures differ (expected | actual)\n";
    const std::size_t height = std::max(actual.size(), rows.size());
    for (std::size_t y = 0; y < height; ++y) {
        const std::string expected_row = y < rows.size() ? rows[y] : "";
        const std::string actual_row = y < actual.size() ? actual[y] : "";
        message << "  " << expected_row
                << std::string(actual_row.size() - std::min(actual_row.size(), expected_row.size()), ' ') << " | "
                << actual_row << (expected_row == actual_row ? "" : "   <- row " + std::to_string(y)) << '\n';
    }
    return ::testing::AssertionFailure() << message.str();
}

}  // namespace test_support
