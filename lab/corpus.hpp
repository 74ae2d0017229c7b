#pragma once

#include "reference.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

// Fixed, seeded inputs: every run of the lab and of the tests sees the same shapes.
namespace lab {

using Polygon = std::vector<ExactPoint>;

struct PolygonCorpus {
    std::string name;
    PixelRect window;  // the pixels compared
    std::vector<Polygon> polygons;
};

// Triangles that tile a region without gaps or overlaps, so each covered pixel is hit once.
struct MeshCase {
    std::string name;
    PixelRect window;
    std::vector<Polygon> triangles;
};

struct SegmentCorpus {
    std::string name;
    PixelRect window;
    std::vector<std::pair<glm::ivec2, glm::ivec2>> segments;
};

// Distances from the origin, in pixels, at which every corpus is placed.
inline constexpr std::int64_t kOffsets[] = {0, 3'000, 300'000};
inline constexpr std::int64_t kFarOffset = 1'000'000;

[[nodiscard]] std::vector<PolygonCorpus> polygon_corpora();
[[nodiscard]] std::vector<MeshCase> mesh_cases();
[[nodiscard]] std::vector<SegmentCorpus> segment_corpora();
// `count` triangles of about `size` pixels across, on the 1/kExactOne grid, inside `window`.
[[nodiscard]] std::vector<Polygon> triangles_of_size(double size, int count, PixelRect window, unsigned seed);
// `count` segments of `length` pixels inside `window`.
[[nodiscard]] std::vector<std::pair<glm::ivec2, glm::ivec2>> segments_of_length(int length, int count, PixelRect window,
                                                                                unsigned seed);

}  // namespace lab
