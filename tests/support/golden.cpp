#include "golden.hpp"

#include <raster/io/webp.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace test_support {
namespace fs = std::filesystem;
namespace {

bool updating() {
    const char* flag = std::getenv("RASTER_UPDATE_SNAPSHOTS");
    return flag != nullptr && std::string(flag) == "1";
}

fs::path snapshot_path(const std::string& name, const std::string& extension) {
    return fs::path(RASTER_SNAPSHOT_DIR) / (name + extension);
}

fs::path diff_path(const std::string& name, const std::string& suffix) {
    const fs::path path = fs::path(RASTER_DIFF_DIR) / (name + suffix);
    fs::create_directories(path.parent_path());
    return path;
}

std::string describe(raster::Rgb colour) {
    return "(" + std::to_string(colour.r) + ", " + std::to_string(colour.g) + ", " + std::to_string(colour.b) + ")";
}

const char* kRegenerate = "if the change is intended: cmake --build <build> --target update-snapshots";

// Differing pixels in magenta over a dimmed copy of the actual image.
raster::Framebuffer diff_image(const raster::Framebuffer& expected, const raster::Framebuffer& actual) {
    raster::Framebuffer diff(actual.width(), actual.height());
    for (int y = 0; y < actual.height(); ++y) {
        for (int x = 0; x < actual.width(); ++x) {
            const raster::Rgb a = actual.pixel(x, y);
            const bool same = expected.pixel(x, y) == a;
            diff.set_pixel(x, y,
                           same ? raster::Rgb{static_cast<std::uint8_t>(a.r / 4), static_cast<std::uint8_t>(a.g / 4),
                                              static_cast<std::uint8_t>(a.b / 4)}
                                : raster::Rgb{255, 0, 255});
        }
    }
    return diff;
}

}  // namespace

::testing::AssertionResult matches_snapshot(const raster::Framebuffer& actual, const std::string& name) {
    const fs::path path = snapshot_path(name, ".webp");
    if (updating()) {
        fs::create_directories(path.parent_path());
        raster::write_webp_still(actual, path, raster::Effort::max);
        return ::testing::AssertionSuccess() << "updated " << path;
    }
    if (!fs::exists(path)) {
        return ::testing::AssertionFailure() << path << " is missing; " << kRegenerate;
    }
    const raster::DecodedWebp decoded = raster::read_webp(path);
    const raster::Framebuffer& expected = decoded.frames.at(0).image;
    if (expected.width() != actual.width() || expected.height() != actual.height()) {
        return ::testing::AssertionFailure()
               << name << ": snapshot is " << expected.width() << "x" << expected.height() << ", render is "
               << actual.width() << "x" << actual.height() << "; " << kRegenerate;
    }
    long differing = 0;
    std::string first;
    for (int y = 0; y < actual.height(); ++y) {
        for (int x = 0; x < actual.width(); ++x) {
            if (expected.pixel(x, y) == actual.pixel(x, y)) continue;
            if (differing++ == 0) {
                first = "(" + std::to_string(x) + ", " + std::to_string(y) + "): expected " +
                        describe(expected.pixel(x, y)) + ", got " + describe(actual.pixel(x, y));
            }
        }
    }
    if (differing == 0) return ::testing::AssertionSuccess();
    const fs::path actual_file = diff_path(name, ".actual.webp");
    const fs::path diff_file = diff_path(name, ".diff.webp");
    raster::write_webp_still(actual, actual_file, raster::Effort::fast);
    raster::write_webp_still(diff_image(expected, actual), diff_file, raster::Effort::fast);
    return ::testing::AssertionFailure() << name << ": " << differing << " pixels differ; first at " << first
                                         << "\n  actual: " << actual_file.string()
                                         << "\n  diff:   " << diff_file.string() << "\n  " << kRegenerate;
}

::testing::AssertionResult matches_digests(const std::vector<std::string>& digests, const std::string& name) {
    const fs::path path = snapshot_path(name, ".digests");
    if (updating()) {
        fs::create_directories(path.parent_path());
        std::ofstream out(path);
        for (const std::string& digest : digests) out << digest << '\n';
        return ::testing::AssertionSuccess() << "updated " << path;
    }
    std::ifstream in(path);
    if (!in) return ::testing::AssertionFailure() << path << " is missing; " << kRegenerate;
    std::vector<std::string> expected;
    for (std::string line; std::getline(in, line);) expected.push_back(line);
    if (expected.size() != digests.size()) {
        return ::testing::AssertionFailure()
               << name << ": " << expected.size() << " digests stored, " << digests.size() << " rendered";
    }
    long differing = 0;
    std::size_t first = 0;
    for (std::size_t i = digests.size(); i-- > 0;) {
        if (digests[i] != expected[i]) {
            ++differing;
            first = i;
        }
    }
    if (differing == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << name << ": " << differing << " frames differ, first is frame " << first
                                         << "; " << kRegenerate;
}

std::string digest_of(const raster::Framebuffer& image) {
    std::uint64_t hash = 14695981039346656037ULL;
    const auto mix = [&hash](std::uint8_t byte) { hash = (hash ^ byte) * 1099511628211ULL; };
    for (const int side : {image.width(), image.height()}) {
        for (int shift = 0; shift < 32; shift += 8) mix(static_cast<std::uint8_t>(side >> shift));
    }
    for (const std::uint8_t byte : image.bytes()) mix(byte);
    std::ostringstream text;
    text << std::hex;
    text.width(16);
    text.fill('0');
    text << hash;
    return text.str();
}

}  // namespace test_support
