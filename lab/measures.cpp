#include "measures.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lab {
namespace {

std::vector<glm::dvec2> on_screen(const Polygon& polygon) {
    std::vector<glm::dvec2> corners;
    for (const ExactPoint& point : polygon) corners.push_back(to_screen(point));
    return corners;
}

template <typename Visit>
void for_each_pixel(const PixelRect& rect, Visit visit) {
    for (std::int64_t y = rect.y; y < std::int64_t{rect.y} + rect.height; ++y) {
        for (std::int64_t x = rect.x; x < std::int64_t{rect.x} + rect.width; ++x) visit(x, y);
    }
}

// How many pixels of the 3x3 block around (x, y) lie in the rectangle and are covered.
int covered_around(const Coverage& coverage, std::int64_t x, std::int64_t y) {
    int covered = 0;
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            covered += coverage.contains(x + dx, y + dy) && coverage.at(x + dx, y + dy) != 0;
        }
    }
    return covered;
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double length2 = ab.x * ab.x + ab.y * ab.y;
    const double t = length2 == 0.0 ? 0.0 : std::clamp(((p - a).x * ab.x + (p - a).y * ab.y) / length2, 0.0, 1.0);
    const glm::dvec2 nearest = a + t * ab;
    return std::hypot(p.x - nearest.x, p.y - nearest.y);
}

}  // namespace

FillAccuracy measure_polygons(const FillMethod& method, const PolygonCorpus& corpus) {
    FillAccuracy result;
    Coverage expected(corpus.window);
    Coverage actual(corpus.window);
    for (const Polygon& polygon : corpus.polygons) {
        expected.clear();
        actual.clear();
        reference_polygon(polygon, expected);
        method.fill(on_screen(polygon), actual);
        for_each_pixel(corpus.window, [&](std::int64_t x, std::int64_t y) {
            result.reference_pixels += expected.at(x, y);
            result.mismatches += expected.at(x, y) != actual.at(x, y);
        });
    }
    return result;
}

FillAccuracy measure_mesh(const FillMethod& method, const MeshCase& mesh) {
    FillAccuracy result;
    Coverage expected(mesh.window);
    Coverage actual(mesh.window);
    for (const Polygon& triangle : mesh.triangles) {
        reference_polygon(triangle, expected);
        method.fill(on_screen(triangle), actual);
    }
    for_each_pixel(mesh.window, [&](std::int64_t x, std::int64_t y) {
        result.reference_pixels += expected.at(x, y);
        result.mismatches += expected.at(x, y) != actual.at(x, y);
        result.double_hits += actual.at(x, y) > 1;
        result.cracks += actual.at(x, y) == 0 && covered_around(expected, x, y) == 9;
    });
    return result;
}

double measure_motion(const FillMethod& method, std::int64_t offset) {
    const glm::dvec2 base{static_cast<double>(offset) + 8.0, static_cast<double>(offset) + 9.0};
    const std::array<glm::dvec2, 3> shape{{{0.0, 0.0}, {13.25, 2.125}, {4.75, 11.875}}};
    Coverage coverage({static_cast<int>(offset), static_cast<int>(offset), 40, 40});
    double worst = 0.0;
    for (int frame = 0; frame < 64; ++frame) {
        const glm::dvec2 shift{frame / 16.0, frame / 32.0};
        std::vector<glm::dvec2> corners;
        glm::dvec2 centroid{0.0, 0.0};
        for (const glm::dvec2 corner : shape) {
            corners.push_back(base + shift + corner);
            centroid += (shift + corner) / 3.0;  // relative to base, to keep the sums exact
        }
        coverage.clear();
        method.fill(corners, coverage);
        glm::dvec2 sum{0.0, 0.0};
        std::int64_t count = 0;
        for_each_pixel(coverage.rect(), [&](std::int64_t x, std::int64_t y) {
            if (coverage.at(x, y) == 0) return;
            sum += glm::dvec2(static_cast<double>(x) - base.x, static_cast<double>(y) - base.y);
            ++count;
        });
        if (count == 0) return INFINITY;
        const glm::dvec2 error = sum / static_cast<double>(count) - centroid;
        worst = std::max(worst, std::hypot(error.x, error.y));
    }
    return worst;
}

LineAccuracy measure_segments(const LineMethod& method, const SegmentCorpus& corpus) {
    LineAccuracy result;
    const PixelRect& w = corpus.window;
    raster::Framebuffer drawn(w.width, w.height);
    Coverage expected(w);
    for (const auto& segment : corpus.segments) {
        const glm::ivec2 from = segment.first;
        const glm::ivec2 to = segment.second;
        drawn.clear({});
        expected.clear();
        result.steps += method.draw(drawn, {w.x, w.y}, from, to);
        reference_line(from, to, expected);
        std::int64_t drawn_count = 0;
        std::int64_t expected_count = 0;
        for_each_pixel(w, [&](std::int64_t x, std::int64_t y) {
            const bool lit = drawn.pixel(static_cast<int>(x - w.x), static_cast<int>(y - w.y)) != raster::Rgb{};
            const bool ideal = expected.at(x, y) != 0;
            drawn_count += lit;
            expected_count += ideal;
            result.mismatches += lit != ideal;
            if (!lit) return;
            result.max_distance = std::max(
                result.max_distance, distance_to_segment(glm::dvec2(static_cast<double>(x), static_cast<double>(y)),
                                                         glm::dvec2(from), glm::dvec2(to)));
            const bool near = covered_around(expected, x, y) > 0;
            // A neighbour outside the window may be the reference pixel; only judge inner pixels.
            const bool inner = x > w.x && y > w.y && x < w.x + w.width - 1 && y < w.y + w.height - 1;
            result.outside_neighbourhood += !near && inner;
        });
        result.reference_pixels += expected_count;
        const std::int64_t difference = std::abs(drawn_count - expected_count);
        result.count_difference += difference;
        result.max_count_difference = std::max(result.max_count_difference, difference);
    }
    return result;
}

}  // namespace lab
