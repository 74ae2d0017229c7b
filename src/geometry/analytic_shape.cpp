#include <raster/geometry/analytic_shape.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace raster {
namespace {

// Both roots of |o + t d|^2 = radius^2, smaller first, if the line meets the sphere.
std::optional<std::pair<double, double>> sphere_roots(glm::dvec3 o, glm::dvec3 d, double radius) {
    const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
    const double discriminant = b * b - a * c;
    if (!(discriminant >= 0.0) || !(a > 0.0)) return std::nullopt;
    const double root = std::sqrt(discriminant);
    // The numerically stable pair: no cancellation between b and root.
    const double q = b >= 0.0 ? -(b + root) : -(b - root);
    const double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
    return std::pair{std::min(t0, t1), std::max(t0, t1)};
}

// The largest eigenvalue of a symmetric positive semi-definite matrix, by power iteration.
double largest_eigenvalue(const glm::dmat3& m) {
    glm::dvec3 v(0.577, 0.579, 0.575);
    double value = 0.0;
    for (int i = 0; i < 64; ++i) {
        const glm::dvec3 next = m * v;
        value = glm::length(next);
        if (!(value > 0.0) || !std::isfinite(value)) return value > 0.0 ? value : 0.0;
        v = next / value;
    }
    return value;
}

}  // namespace

double distance_to_surface(ShapeKind shape, glm::dvec3 p) noexcept {
    if (shape == ShapeKind::sphere) return glm::length(p) - 1.0;
    const glm::dvec2 q(std::hypot(p.x, p.z) - kTorusRingRadius, p.y);
    return glm::length(q) - kTorusTubeRadius;
}

glm::dvec3 surface_normal(ShapeKind shape, glm::dvec3 p) noexcept {
    if (shape == ShapeKind::sphere) return glm::normalize(p);
    const double rho = std::hypot(p.x, p.z);
    if (!(rho > 0.0)) return {0.0, p.y >= 0.0 ? 1.0 : -1.0, 0.0};
    const glm::dvec3 centre(kTorusRingRadius * p.x / rho, 0.0, kTorusRingRadius * p.z / rho);
    return glm::normalize(p - centre);
}

std::optional<double> first_hit(ShapeKind shape, glm::dvec3 o, glm::dvec3 d) noexcept {
    if (shape == ShapeKind::sphere) {
        const auto roots = sphere_roots(o, d, 1.0);
        if (!roots) return std::nullopt;
        return roots->first;
    }
    const auto bounds = sphere_roots(o, d, kTorusRingRadius + kTorusTubeRadius + 1e-9);
    if (!bounds) return std::nullopt;
    const double speed = glm::length(d);
    double t = bounds->first;
    for (int step = 0; step < 100000 && t <= bounds->second; ++step) {
        const double distance = distance_to_surface(shape, o + t * d);
        if (distance < 1e-12) return t;
        t += distance / speed;
    }
    return std::nullopt;
}

Stretch model_stretch(const glm::mat4& model) noexcept {
    const glm::dmat3 m{glm::mat3(model)};
    const glm::dmat3 gram = glm::transpose(m) * m;
    const double most = std::sqrt(largest_eigenvalue(gram));
    if (!(std::abs(glm::determinant(gram)) > 0.0)) return {0.0, most};
    const double inverse_most = largest_eigenvalue(glm::inverse(gram));
    return {inverse_most > 0.0 ? 1.0 / std::sqrt(inverse_most) : 0.0, most};
}

}  // namespace raster
