// OBJ faces of any shape, concave or cut by a slit, read into triangles that tile exactly their outline.
#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

using raster::Model;
using raster::parse_obj;

namespace {

// The OBJ text of one face in the XY plane, its corners in the order given.
std::string face_obj(const std::vector<glm::dvec2>& outline) {
    std::string obj;
    for (const glm::dvec2& p : outline) obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " 0\n";
    obj += "f";
    for (std::size_t i = 1; i <= outline.size(); ++i) obj += " " + std::to_string(i);
    return obj + "\n";
}

double shoelace(const std::vector<glm::dvec2>& outline) {
    double twice = 0.0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

// Crossings of a ray to +x: odd inside, even outside (a slit of no width crosses twice).
bool inside(const std::vector<glm::dvec2>& outline, glm::dvec2 p) {
    bool odd = false;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const glm::dvec2 a = outline[i], b = outline[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) odd = !odd;
    }
    return odd;
}

std::vector<glm::dvec2> regular(int corners, double radius, bool clockwise) {
    std::vector<glm::dvec2> ring;
    for (int i = 0; i < corners; ++i) {
        const double angle = (clockwise ? -1.0 : 1.0) * 2.0 * std::numbers::pi * i / corners;
        ring.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    return ring;
}

// Every facet of the model's one mesh, in the XY plane, must tile the outline: the areas add up
// to the polygon's, and each sample point inside is covered once, each outside never.
void expect_tiles(const std::vector<glm::dvec2>& outline, const std::string& name) {
    const Model model = parse_obj(face_obj(outline), "");
    ASSERT_EQ(model.parts.size(), 1U) << name;
    const raster::Mesh& mesh = model.parts[0].mesh;
    EXPECT_LE(mesh.facets.size(), outline.size() - 2) << name;
    double area = 0.0;
    std::vector<std::array<glm::dvec2, 3>> triangles;
    for (const raster::Facet& facet : mesh.facets) {
        std::array<glm::dvec2, 3> t;
        for (int k = 0; k < 3; ++k)
            t[static_cast<std::size_t>(k)] = glm::dvec2(mesh.positions[facet.corners[static_cast<std::size_t>(k)]]);
        area += std::abs(shoelace({t[0], t[1], t[2]}));
        triangles.push_back(t);
    }
    // Positions are floats: the areas agree to float precision.
    EXPECT_NEAR(area, std::abs(shoelace(outline)), 1e-5 * std::abs(shoelace(outline))) << name;
    glm::dvec2 low(1e9), high(-1e9);
    for (const glm::dvec2& p : outline) low = glm::min(low, p), high = glm::max(high, p);
    int wrong = 0;
    for (int i = 0; i < 97; ++i) {
        for (int j = 0; j < 89; ++j) {
            const glm::dvec2 p = low + (high - low) * glm::dvec2((i + 0.5113) / 97.0, (j + 0.4871) / 89.0);
            int covered = 0;
            for (const auto& t : triangles) {
                const double d0 = shoelace({t[0], t[1], p}), d1 = shoelace({t[1], t[2], p}),
                             d2 = shoelace({t[2], t[0], p});
                if ((d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0)) ++covered;
            }
            if (covered != (inside(outline, p) ? 1 : 0)) ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0) << name;
}

}  // namespace

TEST(ObjFile, FacesOfAnyShapeAreSplitIntoExactlyTheirOwnArea) {
    // A LightWave-style ring: the outer circle one way, a slit, the inner circle back; 66 corners, 64 distinct.
    std::vector<glm::dvec2> ring = regular(32, 2.0, false);
    ring.push_back(ring[0]);
    const std::vector<glm::dvec2> hole = regular(32, 1.0, true);
    ring.insert(ring.end(), hole.begin(), hole.end());
    ring.push_back(hole[0]);
    ASSERT_EQ(ring.size(), 66U);
    std::vector<glm::dvec2> star;
    for (int i = 0; i < 10; ++i) {
        const double angle = std::numbers::pi * i / 5.0, radius = i % 2 == 0 ? 1.0 : 0.38;
        star.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    const std::vector<glm::dvec2> ell{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    std::vector<glm::dvec2> comb{{0, 0}, {9, 0}, {9, 1}};
    for (int tooth = 4; tooth >= 0; --tooth) {
        comb.emplace_back(2 * tooth + 1, 3);
        comb.emplace_back(2 * tooth, 3);
        if (tooth > 0) comb.emplace_back(2 * tooth, 1), comb.emplace_back(2 * tooth - 1, 1);
    }
    expect_tiles(ring, "ring cut by a slit");
    expect_tiles(star, "star");
    expect_tiles(ell, "L");
    expect_tiles(comb, "comb");
    expect_tiles(std::vector<glm::dvec2>(ell.rbegin(), ell.rend()), "L wound the other way");
}
