#include <raster/shade/linear_lighting.hpp>

#include "shade/simd_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

// LinearLighting::shade in lanes: each step is the scalar one's, in the same order, so that every
// lane gives the scalar result exactly; the rare cases the scalar code takes another path for
// (offsets too large or too small for a float square, non-whole shininess) are done lane by lane.
namespace raster {

namespace {

using lanes::Floats;
using lanes::Mask;
using lanes::Vec3;
namespace stdx = lanes::stdx;

// DepthDarkening::factor per lane.
Floats darkened(const DepthDarkening& d, const Floats& depth) noexcept {
    Floats out = 1.0F - (1.0F - d.floor) * (depth - d.start) / (d.end - d.start);
    stdx::where(!(depth < d.end), out) = d.floor;
    stdx::where(!(depth > d.start), out) = 1.0F;
    return out;
}

// LinearLighting::attenuated per lane.
Floats attenuated_lanes(const PreparedPointLight& light, const Floats& distance, float brightest) noexcept {
    const Falloff& f = light.falloff;
    // Zero terms stay zero at an infinite distance (0 * inf would be NaN).
    const Floats linear = f.linear == 0.0F ? Floats(0.0F) : f.linear * distance;
    const Floats quadratic = f.quadratic == 0.0F ? Floats(0.0F) : f.quadratic * distance * distance;
    Floats received = light.intensity / (f.constant + linear + quadratic);
    stdx::where(received < -brightest, received) = -brightest;  // std::clamp's order
    stdx::where(brightest < received, received) = brightest;
    return received;
}

}  // namespace

// Flattened: GCC leaves the eight-lane helpers out of line otherwise, and the calls cost more than the arithmetic.
[[gnu::flatten]] void LinearLighting::shade_lanes(const LaneVec3& positions, const LaneVec3& normals,
                                                  const LaneRgb& diffuse_colours, std::span<Rgb> out) const noexcept {
    const int count = static_cast<int>(std::min<std::size_t>(out.size(), kLanes));
    const Vec3 position = lanes::load(positions), normal = lanes::unit_or_zero(lanes::load(normals));
    // The direction and distance from each point toward `light`, as toward_point() finds them.
    const auto toward = [&](glm::vec3 light, Vec3& unit, Floats& distance) {
        const Vec3 offset = lanes::broadcast(light.x, light.y, light.z) - position;
        const Floats squared = lanes::dot(offset, offset);
        const Mask in_float =
            squared >= std::numeric_limits<float>::min() && squared < Floats(std::numeric_limits<float>::infinity());
        distance = stdx::sqrt(squared);
        unit = offset / distance;
        if (stdx::all_of(in_float)) return;
        for (int i = 0; i < count; ++i) {
            const auto k = static_cast<std::size_t>(i);
            if (in_float[k]) continue;
            const Toward precise = toward_point_precisely(light, {positions.x[k], positions.y[k], positions.z[k]});
            unit.x[k] = precise.unit.x, unit.y[k] = precise.unit.y, unit.z[k] = precise.unit.z,
            distance[k] = precise.distance;
        }
    };
    Vec3 to_eye = lanes::broadcast(to_eye_.x, to_eye_.y, to_eye_.z);
    if (eye_ && power_.enabled()) {
        Floats unused;
        toward(*eye_, to_eye, unused);
    }
    Floats diffuse(0.0F), specular(0.0F);
    for (const PreparedLight& light : directional_) {
        const Vec3 toward_light = lanes::broadcast(light.toward.x, light.toward.y, light.toward.z);
        diffuse += light.intensity * lanes::positive_part(lanes::dot(normal, toward_light));
        if (power_.enabled()) {
            const Vec3 half = eye_ ? lanes::unit_or_zero(toward_light + to_eye)
                                   : lanes::broadcast(light.half.x, light.half.y, light.half.z);
            specular += light.intensity * lanes::powered(power_, lanes::positive_part(lanes::dot(normal, half)));
        }
    }
    for (const PreparedPointLight& light : points_) {
        Vec3 unit;
        Floats distance;
        toward(light.position, unit, distance);
        const Mask lit = distance > 0.0F;  // at the light itself: no direction to light from
        if (stdx::none_of(lit)) continue;
        const Floats arriving = attenuated_lanes(light, distance, kBrightest);
        stdx::where(lit, diffuse) += arriving * lanes::positive_part(lanes::dot(normal, unit));
        if (power_.enabled()) {
            stdx::where(lit, specular) +=
                arriving *
                lanes::powered(power_, lanes::positive_part(lanes::dot(normal, lanes::unit_or_zero(unit + to_eye))));
        }
    }
    if (darkening_ && eye_) {
        const Vec3 away = lanes::broadcast(-to_eye_.x, -to_eye_.y, -to_eye_.z);
        const Floats dimmed =
            darkened(*darkening_, lanes::dot(position - lanes::broadcast(eye_->x, eye_->y, eye_->z), away));
        diffuse *= dimmed;
        specular *= dimmed;
    }
    // A zero normal receives nothing.
    const Mask unlit = lanes::dot(normal, normal) == 0.0F;
    stdx::where(unlit, diffuse) = 0.0F;
    stdx::where(unlit, specular) = 0.0F;
    const LinearMaterial& m = material_;
    const Floats r = m.emissive.r + lanes::load(diffuse_colours.r) * diffuse + m.specular.r * specular;
    const Floats g = m.emissive.g + lanes::load(diffuse_colours.g) * diffuse + m.specular.g * specular;
    const Floats b = m.emissive.b + lanes::load(diffuse_colours.b) * diffuse + m.specular.b * specular;
    LaneRgb linear;
    lanes::store(r, linear.r), lanes::store(g, linear.g), lanes::store(b, linear.b);
    srgb_from_linear(linear, out.first(static_cast<std::size_t>(count)));
}

}  // namespace raster
