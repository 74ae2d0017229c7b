// One property over a table of outlines; stays whole so that the shapes read side by side.
#include "geometry/polygon_triangles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

using raster::detail::triangles_of_polygon;
using Outline = std::vector<glm::dvec2>;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

namespace {

double cross(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// Twice the signed area, by the shoelace formula.
double twice_area(const Outline& outline) {
    double sum = 0.0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        sum += a.x * b.y - b.x * a.y;
    }
    return sum;
}

// How often the outline winds around p: zero outside and in a hole, as a slit's two edges cancel.
int winding_number(const Outline& outline, glm::dvec2 p) {
    int winding = 0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        if (a.y <= p.y && p.y < b.y && cross(a, b, p) > 0.0) ++winding;
        if (b.y <= p.y && p.y < a.y && cross(a, b, p) < 0.0) --winding;
    }
    return winding;
}

bool strictly_inside(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 p) {
    const double d0 = cross(a, b, p), d1 = cross(b, c, p), d2 = cross(c, a, p);
    return (d0 > 0.0 && d1 > 0.0 && d2 > 0.0) || (d0 < 0.0 && d1 < 0.0 && d2 < 0.0);
}

// Where the 2D outline is put in 3D: flat in z = 0, upright in a plane x = const (mirrored), or
// turned about a skew axis and moved away from the origin.
enum class Pose { kFlat, kUpright, kTilted };

std::vector<glm::dvec3> placed(const Outline& outline, Pose pose) {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 2.0, 3.0));
    const double cos_angle = std::cos(1.1), sin_angle = std::sin(1.1);
    std::vector<glm::dvec3> corners;
    for (const glm::dvec2 p : outline) {
        const glm::dvec3 flat(p, 0.0);
        if (pose == Pose::kFlat) corners.push_back(flat);
        if (pose == Pose::kUpright) corners.emplace_back(2.5, p.y, p.x);
        if (pose == Pose::kTilted) {  // Rodrigues' rotation formula
            corners.push_back(glm::dvec3(5.0, -3.0, 2.0) + flat * cos_angle + glm::cross(axis, flat) * sin_angle +
                              axis * glm::dot(axis, flat) * (1.0 - cos_angle));
        }
    }
    return corners;
}

// n - 2 triangles of three distinct corners each, every corner used.
void expect_valid_indices(const Triangles& triangles, std::size_t n) {
    ASSERT_EQ(triangles.size(), n - 2);
    std::vector<bool> used(n);
    for (const auto& t : triangles) {
        ASSERT_TRUE(t[0] < n && t[1] < n && t[2] < n);
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
        used[t[0]] = used[t[1]] = used[t[2]] = true;
    }
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
}

// The triangles of the outline keep its winding, their areas add up to its area, and they cover
// each point of a columns x rows grid (offset off every edge) once if inside the outline, else never.
void expect_covers_once(const Outline& outline, const Triangles& triangles, int columns, int rows) {
    ASSERT_NO_FATAL_FAILURE(expect_valid_indices(triangles, outline.size()));
    const double area = twice_area(outline);
    double sum = 0.0;
    for (const auto& t : triangles) {
        const double part = cross(outline[t[0]], outline[t[1]], outline[t[2]]);
        EXPECT_GE(part * std::copysign(1.0, area), -1e-12 * std::abs(area)) << t[0] << " " << t[1] << " " << t[2];
        sum += std::abs(part);
    }
    EXPECT_NEAR(sum, std::abs(area), 1e-9 * std::abs(area));

    glm::dvec2 low = outline[0], high = outline[0];
    for (const glm::dvec2 p : outline) low = glm::min(low, p), high = glm::max(high, p);
    const glm::dvec2 step = (high - low) / glm::dvec2(columns, rows);
    const auto sample = [&](int i, int j) { return low + glm::dvec2(i + 0.41421356237, j + 0.73205080757) * step; };
    std::vector<int> covered(static_cast<std::size_t>(columns * rows));
    for (const auto& t : triangles) {
        const glm::dvec2 a = outline[t[0]], b = outline[t[1]], c = outline[t[2]];
        const glm::ivec2 first = glm::max(glm::ivec2((glm::min(a, glm::min(b, c)) - low) / step) - 1, 0);
        const glm::ivec2 last =
            glm::min(glm::ivec2((glm::max(a, glm::max(b, c)) - low) / step) + 1, glm::ivec2(columns - 1, rows - 1));
        for (int j = first.y; j <= last.y; ++j) {
            for (int i = first.x; i <= last.x; ++i) {
                covered[static_cast<std::size_t>(j * columns + i)] += strictly_inside(a, b, c, sample(i, j));
            }
        }
    }
    int wrong = 0;
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
            const int expected = winding_number(outline, sample(i, j)) != 0 ? 1 : 0;
            const int actual = covered[static_cast<std::size_t>(j * columns + i)];
            if (actual != expected && ++wrong <= 3) {
                const glm::dvec2 p = sample(i, j);
                ADD_FAILURE() << "(" << p.x << ", " << p.y << ") covered " << actual << " times";
            }
        }
    }
    EXPECT_EQ(wrong, 0);
}

// Both windings, each flat, upright and tilted.
void expect_triangulated_in_every_pose(Outline outline, int columns = 150, int rows = 150) {
    for (const bool reversed : {false, true}) {
        if (reversed) std::reverse(outline.begin(), outline.end());
        for (const Pose pose : {Pose::kFlat, Pose::kUpright, Pose::kTilted}) {
            SCOPED_TRACE(testing::Message() << (reversed ? "reversed, " : "") << "pose " << static_cast<int>(pose));
            expect_covers_once(outline, triangles_of_polygon(placed(outline, pose)), columns, rows);
        }
    }
}

glm::dvec2 on_circle(double radius, double angle) { return radius * glm::dvec2(std::cos(angle), std::sin(angle)); }

Outline star(int points, double outer, double inner) {
    Outline outline;
    for (int k = 0; k < 2 * points; ++k) {
        outline.push_back(on_circle(k % 2 == 0 ? outer : inner, k * std::numbers::pi / points));
    }
    return outline;
}

// An annulus of two n-gons cut open along a slit from the outer corner 0 to the inner corner 0, as
// LightWave writes one: outer ring one way, inner the other, both ends of the slit twice.
Outline ring_cut_by_slit(int sides, double outer, double inner) {
    const auto angle = [sides](int k) { return 2.0 * std::numbers::pi * (k % sides) / sides; };
    Outline outline;
    for (int k = 0; k <= sides; ++k) outline.push_back(on_circle(outer, angle(k)));
    for (int k = sides; k >= 0; --k) outline.push_back(on_circle(inner, angle(k)));
    return outline;
}

// Teeth 0.25 wide and 2.5 long on a bar 0.5 high, one per unit of width: 4 * teeth corners.
Outline comb(int teeth) {
    const double width = teeth - 1 + 0.25;
    Outline outline{{0.0, 0.0}, {width, 0.0}};
    for (int i = teeth - 1; i >= 0; --i) {
        outline.insert(outline.end(), {{i + 0.25, 3.0}, {i, 3.0}});
        if (i > 0) outline.insert(outline.end(), {{i, 0.5}, {i - 0.75, 0.5}});
    }
    return outline;
}

// A band 0.5 wide winding three times around the origin with a pitch of 1.
Outline spiral(int corners) {
    const int side = corners / 2;
    Outline outline(static_cast<std::size_t>(corners));
    for (int k = 0; k < side; ++k) {
        const double angle = 6.0 * std::numbers::pi * k / (side - 1);
        const double radius = 1.0 + angle / (2.0 * std::numbers::pi);
        outline[static_cast<std::size_t>(k)] = on_circle(radius + 0.25, angle);
        outline[static_cast<std::size_t>(corners - 1 - k)] = on_circle(radius - 0.25, angle);
    }
    return outline;
}

}  // namespace

TEST(PolygonTriangles, TriangleComesBackAsItIs) {
    const std::vector<glm::dvec3> corners{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(triangles_of_polygon(corners), (Triangles{{0, 1, 2}}));
}

TEST(PolygonTriangles, ConvexPolygonCoversItsAreaOnce) {
    expect_triangulated_in_every_pose({{0, 0}, {3, -1}, {5, 1}, {4, 3}, {1, 3.5}, {-1, 2}});
}

TEST(PolygonTriangles, CollinearCornersCoverTheirAreaOnce) {
    expect_triangulated_in_every_pose({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {1.5, 2}, {0, 2}, {0, 1}});
    expect_triangulated_in_every_pose(
        {{0, 0}, {2, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {2, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 1.5}});
}

TEST(PolygonTriangles, RepeatedConsecutiveCornersCoverTheirAreaOnce) {
    expect_triangulated_in_every_pose({{3, 1}, {1, 1}, {1, 1}, {1, 4}, {0, 4}, {0, 0}, {0, 0}, {0, 0}, {3, 0}, {3, 1}});
}

TEST(PolygonTriangles, LShapeCoversItsAreaOnce) {
    expect_triangulated_in_every_pose({{3, 1}, {1, 1}, {1, 4}, {0, 4}, {0, 0}, {3, 0}});
}

TEST(PolygonTriangles, StarCoversItsAreaOnce) { expect_triangulated_in_every_pose(star(5, 1.0, 0.38)); }

TEST(PolygonTriangles, CombWithThinTeethCoversItsAreaOnce) { expect_triangulated_in_every_pose(comb(8), 300, 60); }

TEST(PolygonTriangles, RingCutBySlitCoversItsAreaOnce) {
    // A square annulus with the slit from (0, 0) to (1, 1): 10 corners, 8 distinct.
    expect_triangulated_in_every_pose({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
    expect_triangulated_in_every_pose(ring_cut_by_slit(4, 2.0, 1.0));
}

TEST(PolygonTriangles, LightWaveRingOf66CornersCoversItsAreaOnce) {
    const Outline ring = ring_cut_by_slit(32, 1.0, 0.6);
    ASSERT_EQ(ring.size(), 66U);
    expect_triangulated_in_every_pose(ring, 150, 150);
    expect_triangulated_in_every_pose(ring_cut_by_slit(32, 1.0, 0.95), 200, 200);  // a thin ring
}

TEST(PolygonTriangles, SlitsAndCracksOfOtherShapesCoverTheirAreaOnce) {
    // A slit from a hole's corner at a slant, so that one visit of that corner is reflex.
    expect_triangulated_in_every_pose(
        {{1.6, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1.6, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
    // Two holes, each with its own slit.
    expect_triangulated_in_every_pose({{0, 0},
                                       {1.5, 0},
                                       {1, 1},
                                       {1, 2},
                                       {2, 2},
                                       {2, 1},
                                       {1, 1},
                                       {1.5, 0},
                                       {4.5, 0},
                                       {5, 1},
                                       {4, 1},
                                       {4, 2},
                                       {5, 2},
                                       {5, 1},
                                       {4.5, 0},
                                       {6, 0},
                                       {6, 3},
                                       {0, 3}});
    // A crack into a square, which has no area of its own.
    expect_triangulated_in_every_pose({{0, 0}, {3, 1}, {0, 0}, {4, 0}, {4, 4}, {0, 4}});
}

TEST(PolygonTriangles, PinchedFaceCoversItsAreaOnce) {
    // Two lobes that share one corner, which is thus visited twice.
    expect_triangulated_in_every_pose({{0, 0}, {2, -1}, {2, 1}, {0, 0}, {-2, 1}, {-2, -1}});
    expect_triangulated_in_every_pose({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {0, 0}, {1, 2}, {1, 3}, {0, 3}});
}

TEST(PolygonTriangles, CombOf1024CornersCoversItsAreaOnce) {
    const Outline teeth = comb(256);
    ASSERT_EQ(teeth.size(), 1024U);
    expect_triangulated_in_every_pose(teeth, 1024, 6);
}

TEST(PolygonTriangles, SpiralOf1024CornersCoversItsAreaOnce) {
    expect_triangulated_in_every_pose(spiral(1024), 100, 100);
}

TEST(PolygonTriangles, CollinearCornersWithoutAreaStillGiveNMinus2Triangles) {
    std::vector<glm::dvec3> corners;
    for (const double t : {0.0, 1.0, 3.0, 2.0, 5.0, -1.0, 4.0, 4.0}) {
        corners.push_back(glm::dvec3(1, -2, 3) + t * glm::dvec3(0.1, 0.2, 0.3));
    }
    expect_valid_indices(triangles_of_polygon(corners), corners.size());
}

TEST(PolygonTriangles, CoincidentCornersStillGiveNMinus2Triangles) {
    const std::vector<glm::dvec3> corners(7, glm::dvec3(1.0, 2.0, 3.0));
    expect_valid_indices(triangles_of_polygon(corners), corners.size());
}

TEST(PolygonTriangles, SelfIntersectingCornersStillGiveNMinus2Triangles) {
    Outline pentagram;
    for (int k = 0; k < 5; ++k) pentagram.push_back(on_circle(1.0, 4.0 * std::numbers::pi * k / 5));
    expect_valid_indices(triangles_of_polygon(placed(pentagram, Pose::kTilted)), pentagram.size());
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::vector<glm::dvec3> scattered(1024);
    for (glm::dvec3& p : scattered) p = {coordinate(random), coordinate(random), coordinate(random)};
    expect_valid_indices(triangles_of_polygon(scattered), scattered.size());
}
