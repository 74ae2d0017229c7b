#include "scene_lab.hpp"

#include "rasterize/setup_ortho.hpp"

#include <raster/geometry/shapes.hpp>
#include <raster/shade/shaders.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <glm/ext/matrix_transform.hpp>

namespace lab {
namespace {

constexpr int kSize = 400;
constexpr raster::Rgb kFirst{255, 0, 0}, kSecond{0, 0, 255};
// The depth range fixed-point codes span: every surface here lies 0 to 2 in front of the eye.
constexpr double kNear = 0.0, kFar = 2.0;

// A view depth rounded to one of 2^bits codes over [kNear, kFar], kept in the float buffer.
struct FixedDepth {
    double steps;
    [[nodiscard]] float operator()(float depth) const noexcept {
        const double unit = std::clamp((double{depth} - kNear) / (kFar - kNear), 0.0, 1.0);
        return static_cast<float>(std::floor(unit * steps + 0.5));
    }
};

// A square of side 2.4 centred on the origin, facing -Z, moved by `model`.
raster::Mesh square(const glm::mat4& model) {
    return raster::posed(raster::ground_quad({-1.2F, -1.2F, 0}, {-1.2F, 1.2F, 0}, {1.2F, 1.2F, 0}, {1.2F, -1.2F, 0}),
                         model);
}

// The view depth of the plane through a posed square at a pixel centre, in double.
double plane_depth(const raster::Mesh& mesh, const raster::OrthoCamera& camera, int i, int j) {
    const glm::dvec3 origin = camera.world_from_screen(glm::dvec2(i, j), 0.0);
    const glm::dvec3 forward(camera.direction());
    const glm::dvec3 a(mesh.positions[0]), b(mesh.positions[1]), c(mesh.positions[2]);
    const glm::dvec3 normal = glm::cross(b - a, c - b);
    return glm::dot(a - origin, normal) / glm::dot(forward, normal);
}

struct Pair {
    std::string scene;
    double parameter;
    raster::Mesh first;  // drawn first
    raster::Mesh second;
};

std::vector<Pair> pairs() {
    std::vector<Pair> result;
    const glm::mat4 identity(1.0F);
    const glm::vec3 up(0, 1, 0), right(1, 0, 0);
    for (const double degrees : {10.0, 1.0, 0.1, 0.01, 0.001, 0.0001}) {
        const auto angle = static_cast<float>(degrees * std::numbers::pi / 180.0);
        result.push_back({"crossing", degrees, square(glm::rotate(identity, 0.5F, right)),
                          square(glm::rotate(identity, 0.5F, right) * glm::rotate(identity, angle, up))});
    }
    for (const double gap : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
        // Slanted 60 degrees; the far square is drawn last, the case a depth test must decide.
        const glm::mat4 slant = glm::rotate(identity, 1.047F, right);
        result.push_back({"gap", gap, square(slant), square(glm::translate(slant, {0, 0, static_cast<float>(gap)}))});
    }
    return result;
}

template <typename Format>
void draw_pair(raster::Framebuffer& image, raster::DepthBuffer& depth, const raster::OrthoCamera& camera,
               const Pair& pair, Format format) {
    image.clear({0, 0, 0});
    depth.prepare(kSize, kSize);
    const raster::IntensityLighting first({kFirst, 1.0F, 0.0F, {}}, {}, {0, 0, -1});
    const raster::IntensityLighting second({kSecond, 1.0F, 0.0F, {}}, {}, {0, 0, -1});
    raster::detail::draw_facets(image, &depth, camera, pair.first, raster::FlatShader{&first}, format);
    raster::detail::draw_facets(image, &depth, camera, pair.second, raster::FlatShader{&second}, format);
}

template <typename Format>
DepthRow measure(const Pair& pair, const std::string& name, Format format, int repetitions) {
    const raster::OrthoCamera camera(kSize, kSize);
    raster::Framebuffer image(kSize, kSize);
    raster::DepthBuffer depth;
    std::vector<double> times;
    for (int r = 0; r < repetitions; ++r) {
        const auto start = std::chrono::steady_clock::now();
        draw_pair(image, depth, camera, pair, format);
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    DepthRow row{pair.scene, pair.parameter, name, 0, 0, times[times.size() / 2]};
    for (int j = 0; j < kSize; ++j) {
        for (int i = 0; i < kSize; ++i) {
            const raster::Rgb shown = image.pixel(i, j);
            if (shown == raster::Rgb{0, 0, 0}) continue;
            const double a = plane_depth(pair.first, camera, i, j), b = plane_depth(pair.second, camera, i, j);
            if (a == b) continue;  // a true tie: either answer is right
            // Both squares cover the whole middle of the image; compare only where both do.
            const glm::dvec3 at = camera.world_from_screen(glm::dvec2(i, j), 0.0);
            if (std::abs(at.x) > 0.9 || std::abs(at.y) > 0.5) continue;
            ++row.compared_pixels;
            if (shown != (a < b ? kFirst : kSecond)) ++row.wrong_pixels;
        }
    }
    return row;
}

}  // namespace

std::vector<DepthRow> measure_depth(int repetitions) {
    std::vector<DepthRow> rows;
    for (const Pair& pair : pairs()) {
        rows.push_back(measure(pair, "float32", raster::detail::FloatDepth{}, repetitions));
        rows.push_back(measure(pair, "fixed24", FixedDepth{16777215.0}, repetitions));
        rows.push_back(measure(pair, "fixed16", FixedDepth{65535.0}, repetitions));
    }
    return rows;
}

}  // namespace lab
