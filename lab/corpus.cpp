#include "corpus.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace lab {
namespace {

constexpr int kWindow = 48;
// Corpus positions lie on the product's subpixel grid (or a coarser one), so a rasterizer that
// keeps every given position exactly can match the reference pixel for pixel.
constexpr int kSubpixelBits = 8;

// A position on the 1/2^bits pixel grid, in exact units.
ExactPoint on_grid(double x, double y, int bits) {
    const double scale = static_cast<double>(std::int64_t{1} << bits);
    const auto snap = [&](double v) {
        return static_cast<std::int64_t>(std::floor(v * scale + 0.5)) << (kExactBits - bits);
    };
    return {snap(x), snap(y)};
}

PixelRect window_at(std::int64_t offset) {
    return {static_cast<int>(offset), static_cast<int>(offset), kWindow, kWindow};
}

std::string at_offset(const std::string& name, std::int64_t offset) { return name + "@" + std::to_string(offset); }

std::vector<Polygon> random_triangles(std::mt19937& random, int count, double offset, double spread, int bits) {
    std::uniform_real_distribution<double> coordinate(-spread, kWindow + spread);
    std::vector<Polygon> triangles;
    for (int i = 0; i < count; ++i) {
        Polygon triangle;
        for (int k = 0; k < 3; ++k) {
            triangle.push_back(on_grid(offset + coordinate(random), offset + coordinate(random), bits));
        }
        triangles.push_back(triangle);
    }
    return triangles;
}

std::vector<Polygon> slivers(std::mt19937& random, int count, double offset) {
    std::uniform_real_distribution<double> coordinate(-4.0, kWindow + 4.0);
    std::uniform_real_distribution<double> thickness(-0.6, 0.6);
    std::vector<Polygon> triangles;
    for (int i = 0; i < count; ++i) {
        const double ax = coordinate(random), ay = coordinate(random);
        const double bx = coordinate(random), by = coordinate(random);
        const double t = 0.5, length = std::hypot(bx - ax, by - ay) + 1e-9, w = thickness(random);
        const double cx = ax + t * (bx - ax) - w * (by - ay) / length, cy = ay + t * (by - ay) + w * (bx - ax) / length;
        triangles.push_back({on_grid(offset + ax, offset + ay, kSubpixelBits),
                             on_grid(offset + bx, offset + by, kSubpixelBits),
                             on_grid(offset + cx, offset + cy, kSubpixelBits)});
    }
    return triangles;
}

std::vector<Polygon> convex_quads(std::mt19937& random, int count, double offset) {
    std::uniform_real_distribution<double> centre(0.0, kWindow), radius(1.0, 20.0), turn(0.0, 2 * std::numbers::pi);
    std::vector<Polygon> quads;
    for (int i = 0; i < count; ++i) {
        const double cx = centre(random), cy = centre(random), r = radius(random);
        std::vector<double> angles{turn(random), turn(random), turn(random), turn(random)};
        std::sort(angles.begin(), angles.end());
        Polygon quad;
        for (const double a : angles) {
            quad.push_back(on_grid(offset + cx + r * std::cos(a), offset + cy + r * std::sin(a), kSubpixelBits));
        }
        quads.push_back(quad);
    }
    return quads;
}

MeshCase fan(std::mt19937& random, std::int64_t offset, const std::string& name, double radius) {
    const auto o = static_cast<double>(offset);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    const double cx = kWindow / 2.0 + jitter(random), cy = kWindow / 2.0 + jitter(random);
    constexpr std::size_t spokes = 24;
    std::vector<ExactPoint> rim;
    for (std::size_t k = 0; k < spokes; ++k) {
        const double a = 2 * std::numbers::pi * (static_cast<double>(k) + 0.3 * jitter(random)) / spokes;
        rim.push_back(on_grid(o + cx + radius * std::cos(a), o + cy + radius * std::sin(a), kSubpixelBits));
    }
    const ExactPoint hub = on_grid(o + cx, o + cy, kSubpixelBits);
    MeshCase mesh{at_offset(name, offset), window_at(offset), {}};
    for (std::size_t k = 0; k < spokes; ++k) mesh.triangles.push_back({hub, rim[k], rim[(k + 1) % spokes]});
    return mesh;
}

MeshCase grid(std::mt19937& random, std::int64_t offset, const std::string& name, double start, double cell) {
    const auto o = static_cast<double>(offset);
    std::uniform_real_distribution<double> jitter(-0.3 * cell, 0.3 * cell);
    constexpr std::size_t cells = 6;
    std::vector<std::vector<ExactPoint>> points(cells + 1);
    for (std::size_t j = 0; j <= cells; ++j) {
        for (std::size_t i = 0; i <= cells; ++i) {
            points[j].push_back(on_grid(o + start + static_cast<double>(i) * cell + jitter(random),
                                        o + start + static_cast<double>(j) * cell + jitter(random), kSubpixelBits));
        }
    }
    MeshCase mesh{at_offset(name, offset), window_at(offset), {}};
    for (std::size_t j = 0; j < cells; ++j) {
        for (std::size_t i = 0; i < cells; ++i) {
            mesh.triangles.push_back({points[j][i], points[j][i + 1], points[j + 1][i + 1]});
            mesh.triangles.push_back({points[j][i], points[j + 1][i + 1], points[j + 1][i]});
        }
    }
    return mesh;
}

}  // namespace

std::vector<PolygonCorpus> polygon_corpora() {
    std::vector<PolygonCorpus> corpora;
    for (const std::int64_t offset : kOffsets) {
        std::mt19937 random(1234);  // the same shapes at every offset
        const PixelRect window = window_at(offset);
        corpora.push_back(
            {at_offset("grid16", offset), window, random_triangles(random, 300, static_cast<double>(offset), 8.0, 4)});
        corpora.push_back(
            {at_offset("grid256", offset), window, random_triangles(random, 300, static_cast<double>(offset), 8.0, 8)});
        corpora.push_back({at_offset("tiny", offset), window, triangles_of_size(1.5, 300, window, 77)});
        corpora.push_back({at_offset("slivers", offset), window, slivers(random, 200, static_cast<double>(offset))});
        corpora.push_back({at_offset("quads", offset), window, convex_quads(random, 200, static_cast<double>(offset))});
        corpora.push_back({at_offset("huge", offset), window,
                           random_triangles(random, 40, static_cast<double>(offset), 3000.0, kSubpixelBits)});
    }
    return corpora;
}

std::vector<MeshCase> mesh_cases() {
    std::vector<MeshCase> meshes;
    std::vector<std::int64_t> offsets(std::begin(kOffsets), std::end(kOffsets));
    offsets.push_back(kFarOffset);
    offsets.push_back(-kFarOffset);
    for (const std::int64_t offset : offsets) {
        std::mt19937 random(99);
        meshes.push_back(fan(random, offset, "fan", 20.0));
        meshes.push_back(grid(random, offset, "grid", 4.0, 6.5));
        meshes.push_back(grid(random, offset, "offscreen-grid", -20.0, 15.0));
        meshes.push_back(fan(random, offset, "offscreen-fan", 60.0));
    }
    return meshes;
}

std::vector<SegmentCorpus> segment_corpora() {
    std::vector<SegmentCorpus> corpora;
    std::vector<std::int64_t> offsets(std::begin(kOffsets), std::end(kOffsets));
    offsets.push_back(kFarOffset);
    for (const std::int64_t offset : offsets) {
        std::mt19937 random(4321);
        std::uniform_int_distribution<int> coordinate(-16, kWindow + 16);
        SegmentCorpus corpus{at_offset("segments", offset), window_at(offset), {}};
        const int base = static_cast<int>(offset);
        for (int i = 0; i < 500; ++i) {
            corpus.segments.push_back({{base + coordinate(random), base + coordinate(random)},
                                       {base + coordinate(random), base + coordinate(random)}});
        }
        corpora.push_back(corpus);
        SegmentCorpus long_ones{at_offset("long-segments", offset), window_at(offset),
                                segments_of_length(1000, 200, window_at(offset), 8765)};
        corpora.push_back(long_ones);
    }
    return corpora;
}

std::vector<Polygon> triangles_of_size(double size, int count, PixelRect window, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> x(window.x, window.x + window.width - size);
    std::uniform_real_distribution<double> y(window.y, window.y + window.height - size);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Polygon> triangles;
    for (int i = 0; i < count; ++i) {
        const double left = x(random), top = y(random);
        // One corner on each of three sides of a size x size box keeps the triangle about that big.
        triangles.push_back({on_grid(left + size * unit(random), top, kSubpixelBits),
                             on_grid(left + size, top + size * unit(random), kSubpixelBits),
                             on_grid(left, top + size * unit(random), kSubpixelBits)});
    }
    return triangles;
}

std::vector<std::pair<glm::ivec2, glm::ivec2>> segments_of_length(int length, int count, PixelRect window,
                                                                  unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> turn(0.0, 2 * std::numbers::pi);
    std::uniform_int_distribution<int> x(window.x, window.x + window.width - 1);
    std::uniform_int_distribution<int> y(window.y, window.y + window.height - 1);
    std::vector<std::pair<glm::ivec2, glm::ivec2>> segments;
    for (int i = 0; i < count; ++i) {
        const double a = turn(random);
        const glm::ivec2 from{x(random), y(random)};
        const glm::ivec2 to{from.x + static_cast<int>(std::lround(length * std::cos(a))),
                            from.y + static_cast<int>(std::lround(length * std::sin(a)))};
        segments.push_back({from, to});
    }
    return segments;
}

}  // namespace lab
