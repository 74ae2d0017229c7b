#include "geometry/polygon_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raster::detail {

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// Twice the signed area of (a, b, c): positive when they turn counter-clockwise.
double orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The corners in the plane of the face with its dominant axis dropped, mirrored if need be so that
// they run counter-clockwise; empty when the face has no plane (a zero Newell normal).
std::vector<glm::dvec2> counter_clockwise_outline(std::span<const glm::dvec3> corners) {
    glm::dvec3 normal(0.0);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        // Relative to the first corner, so that a face far from the origin keeps its precision.
        const glm::dvec3 p = corners[i] - corners[0];
        const glm::dvec3 q = corners[i + 1 == corners.size() ? 0 : i + 1] - corners[0];
        normal += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
    }
    const glm::dvec3 size = glm::abs(normal);
    if (!(std::max({size.x, size.y, size.z}) > 0.0)) return {};
    const int drop = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    // normal[drop] is twice the area seen along the dropped axis with (u, v) in cyclic order.
    int u = (drop + 1) % 3;
    int v = (drop + 2) % 3;
    if (normal[drop] < 0.0) std::swap(u, v);
    std::vector<glm::dvec2> outline;
    outline.reserve(corners.size());
    for (const glm::dvec3& corner : corners) outline.emplace_back(corner[u], corner[v]);
    return outline;
}

// The corners not yet clipped, as a doubly linked ring, with whether each is convex and an ear. In a
// simple polygon only the neighbours of a clipped corner change status, which keeps clipping O(n^2).
class EarRing {
public:
    explicit EarRing(std::vector<glm::dvec2> outline)
        : points_(std::move(outline)), prev_(points_.size()), next_(points_.size()), convex_(points_.size()),
          ear_(points_.size()), remaining_(points_.size()) {
        glm::dvec2 low = points_[0], high = points_[0];
        for (const glm::dvec2 p : points_) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        const double extent = std::max(high.x - low.x, high.y - low.y);
        const double magnitude = std::max({-low.x, -low.y, high.x, high.y});
        // Orientations below this are rounding noise in coordinates of this magnitude.
        flat_ = 1e-12 * extent * std::max(extent, magnitude);
        for (std::size_t i = 0; i < remaining_; ++i) {
            prev_[i] = i == 0 ? remaining_ - 1 : i - 1;
            next_[i] = i + 1 == remaining_ ? 0 : i + 1;
        }
        recheck_all(0);
    }

    [[nodiscard]] std::size_t size() const { return remaining_; }

    // Every remaining corner's status afresh, for when one might be stale (see triangles_of_polygon).
    void recheck_all(std::size_t start) {
        std::size_t i = start;
        for (std::size_t step = 0; step < remaining_; ++step, i = next_[i]) convex_[i] = turn(i) > flat_;
        for (std::size_t step = 0; step < remaining_; ++step, i = next_[i]) ear_[i] = is_ear(i);
    }

    // The first ear from `start` on in ring order.
    [[nodiscard]] std::optional<std::size_t> find_ear(std::size_t start) const {
        std::size_t i = start;
        for (std::size_t step = 0; step < remaining_; ++step, i = next_[i]) {
            if (ear_[i]) return i;
        }
        return std::nullopt;
    }

    // For when there is no ear (the face crosses itself, or what is left has no area): a flat corner,
    // whose triangle has no area, else the convex corner with the smallest triangle, else `start`.
    [[nodiscard]] std::size_t least_harmful_corner(std::size_t start) const {
        std::optional<std::size_t> best;
        std::size_t i = start;
        for (std::size_t step = 0; step < remaining_; ++step, i = next_[i]) {
            const double area = turn(i);
            if (std::abs(area) <= flat_) return i;
            if (area > 0.0 && (!best || area < turn(*best))) best = i;
        }
        return best.value_or(start);
    }

    // Cuts off corner b with its triangle, and returns the corner after its next one, where the
    // search resumes (so that the triangles do not all fan out of one corner).
    std::size_t clip(std::size_t b, std::vector<Triangle>& triangles) {
        const std::size_t a = prev_[b], c = next_[b];
        triangles.push_back(triangle(a, b, c));
        next_[a] = c;
        prev_[c] = a;
        --remaining_;
        convex_[a] = turn(a) > flat_;
        convex_[c] = turn(c) > flat_;
        ear_[a] = is_ear(a);
        ear_[c] = is_ear(c);
        return next_[c];
    }

    [[nodiscard]] Triangle last_triangle(std::size_t a) const { return triangle(a, next_[a], next_[next_[a]]); }

private:
    static Triangle triangle(std::size_t a, std::size_t b, std::size_t c) {
        return {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(c)};
    }

    [[nodiscard]] double turn(std::size_t i) const {
        return orientation(points_[prev_[i]], points_[i], points_[next_[i]]);
    }

    // +1 or -1 if the edge p -> q crosses the ray from `point` to +x upwards or downwards, else 0.
    static int crossing(glm::dvec2 p, glm::dvec2 q, glm::dvec2 point) {
        if (p.y <= point.y && point.y < q.y && orientation(p, q, point) > 0.0) return 1;
        if (q.y <= point.y && point.y < p.y && orientation(p, q, point) < 0.0) return -1;
        return 0;
    }

    // Whether q lies strictly left of the line from p through r, beyond the noise.
    [[nodiscard]] bool left_of(glm::dvec2 p, glm::dvec2 r, glm::dvec2 q) const { return orientation(p, r, q) > flat_; }

    // A convex corner whose triangle holds no reflex or flat corner (any corner inside implies one),
    // no edge entering it from a corner at one of its own places (a slit's ends only touch it), and
    // which the rest of the ring does not wind around (as a pinched face's leftovers can).
    [[nodiscard]] bool is_ear(std::size_t b) const {
        if (!convex_[b]) return false;
        const std::size_t a = prev_[b], c = next_[b];
        const glm::dvec2 pa = points_[a], pb = points_[b], pc = points_[c];
        const glm::dvec2 centre = (pa + pb + pc) / 3.0;
        int winding = crossing(pa, pc, centre);
        for (std::size_t i = c; i != a; i = next_[i]) {
            winding += crossing(points_[i], points_[next_[i]], centre);
            const glm::dvec2 q = points_[i];
            if (i == c) continue;
            if (q == pa || q == pb || q == pc) {
                // The triangle's angle at q is bounded by the two edges meeting there.
                const glm::dvec2 from = q == pa ? pc : (q == pb ? pa : pb);
                const glm::dvec2 to = q == pa ? pb : (q == pb ? pc : pa);
                const auto enters = [&](glm::dvec2 end) { return left_of(from, q, end) && left_of(q, to, end); };
                if (enters(points_[prev_[i]]) || enters(points_[next_[i]])) return false;
            } else if (!convex_[i] && orientation(pa, pb, q) >= -flat_ && orientation(pb, pc, q) >= -flat_ &&
                       orientation(pc, pa, q) >= -flat_) {
                return false;
            }
        }
        return winding == 0;
    }

    std::vector<glm::dvec2> points_;
    std::vector<std::size_t> prev_;
    std::vector<std::size_t> next_;
    std::vector<bool> convex_;
    std::vector<bool> ear_;
    std::size_t remaining_;
    double flat_ = 0.0;
};

bool is_convex(const std::vector<glm::dvec2>& outline) {
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const std::size_t next = (i + 1) % outline.size(), after = (i + 2) % outline.size();
        if (!(orientation(outline[i], outline[next], outline[after]) > 0.0)) return false;
    }
    return true;
}

// A convex quad along its shorter diagonal, the usual split (and tinyobjloader's, so models of
// quads draw as they did): for a bent quad it keeps the fold across the nearer corners. In float,
// as the positions are stored, so that a near tie falls the same way.
std::vector<Triangle> split_quad(std::span<const glm::dvec3> corners) {
    const auto squared = [&](std::size_t a, std::size_t b) {
        const glm::vec3 d = glm::vec3(corners[b]) - glm::vec3(corners[a]);
        return d.x * d.x + d.y * d.y + d.z * d.z;
    };
    if (squared(0, 2) < squared(1, 3)) return {{0, 1, 2}, {0, 2, 3}};
    return {{0, 1, 3}, {1, 2, 3}};
}

}  // namespace

std::vector<Triangle> triangles_of_polygon(std::span<const glm::dvec3> corners) {
    std::vector<Triangle> triangles;
    if (corners.size() < 3) return triangles;
    if (corners.size() == 3) return {{0, 1, 2}};  // most faces: no plane or ring to build
    triangles.reserve(corners.size() - 2);
    std::vector<glm::dvec2> outline = counter_clockwise_outline(corners);
    if (outline.empty()) {  // no plane, so no area to cover: any n - 2 triangles do
        for (std::uint32_t i = 1; i + 1 < corners.size(); ++i) triangles.push_back({0, i, i + 1});
        return triangles;
    }
    if (corners.size() == 4 && is_convex(outline)) return split_quad(corners);
    EarRing ring(std::move(outline));
    // A face that touches itself can leave a status stale; re-checking costs a first pass, so a
    // budget of a few passes in all keeps garbage O(n^2).
    std::size_t recheck_budget = 4 * corners.size();
    bool fresh = true;
    std::size_t cursor = 0;
    while (ring.size() > 3) {
        const std::optional<std::size_t> ear = ring.find_ear(cursor);
        if (!ear && !fresh && recheck_budget >= ring.size()) {
            recheck_budget -= ring.size();
            ring.recheck_all(cursor);
            fresh = true;
            continue;
        }
        cursor = ring.clip(ear ? *ear : ring.least_harmful_corner(cursor), triangles);
        fresh = false;
    }
    triangles.push_back(ring.last_triangle(cursor));
    return triangles;
}

}  // namespace raster::detail
