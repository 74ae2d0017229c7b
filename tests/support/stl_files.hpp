#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

// STL files written by tests: binary with any header and attribute words, ASCII with any numbers.
namespace test_support {

struct StlFacet {
    std::array<float, 3> normal;
    std::array<std::array<float, 3>, 3> corners;
    std::uint16_t attributes = 0;
};

// A binary STL: `header` padded (or cut) to 80 bytes, the count of `facets` (or `count` when
// given), then each facet's 50 bytes.
[[nodiscard]] std::string stl_binary(const std::vector<StlFacet>& facets, const std::string& header = "",
                                     std::int64_t count = -1);

// An ASCII STL of one solid, numbers written with full float precision.
[[nodiscard]] std::string stl_ascii(const std::vector<StlFacet>& facets, const std::string& name = "test");

// A wavy sphere of 2 × rings × rings triangles, with normals (every seventh zero, so made by the
// reader) and face colours on every third facet when `coloured`; the corners' coordinates include -0.
[[nodiscard]] std::vector<StlFacet> stl_wavy_sphere(int rings, bool coloured = false);

}  // namespace test_support
