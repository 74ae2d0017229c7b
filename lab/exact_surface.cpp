#include "exact_surface.hpp"

#include <raster/geometry/analytic_shape.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace lab {
namespace {

std::uint8_t rounded(double value) {
    if (!(value > 0.0)) return 0;
    return static_cast<std::uint8_t>(std::min(255.0, std::floor(value + 0.5)));
}

}  // namespace

double exact_intensity(const raster::IntensityMaterial& material, std::span<const raster::DirectionalLight> lights,
                       glm::dvec3 normal, glm::dvec3 to_eye) {
    double lit = 0.0;
    for (const raster::DirectionalLight& light : lights) {
        const glm::dvec3 l = glm::normalize(glm::dvec3(light.toward));
        double received = std::max(0.0, glm::dot(normal, l));
        if (material.shininess) {
            received +=
                std::pow(std::max(0.0, glm::dot(normal, glm::normalize(l + to_eye))), double{*material.shininess});
        }
        lit += double{light.intensity} * received;
    }
    return double{material.ambient} + double{material.diffuse} * lit;
}

ExactImage ray_cast(const raster::OrthoCamera& camera, int width, int height, std::span<const ExactObject> objects,
                    std::span<const raster::DirectionalLight> lights, raster::Rgb background) {
    const auto pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    ExactImage image{raster::Framebuffer(width, height), std::vector<std::uint8_t>(pixels, 0),
                     std::vector<double>(pixels, std::numeric_limits<double>::infinity())};
    image.colour.clear(background);
    const glm::dvec3 forward(camera.direction());
    const glm::dvec3 to_eye = -glm::normalize(forward);
    struct Prepared {
        glm::dmat4 object_from_world;
        glm::dmat3 normal_matrix;
    };
    std::vector<Prepared> prepared;
    for (const ExactObject& object : objects) {
        const glm::dmat4 model(object.model);
        prepared.push_back({glm::inverse(model), glm::transpose(glm::inverse(glm::dmat3(model)))});
    }
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            const glm::dvec3 origin = camera.world_from_screen(glm::dvec2(i, j), 0.0);
            double nearest = std::numeric_limits<double>::infinity();
            std::optional<raster::Rgb> colour;
            for (std::size_t k = 0; k < objects.size(); ++k) {
                const glm::dvec3 o(prepared[k].object_from_world * glm::dvec4(origin, 1.0));
                const glm::dvec3 d(prepared[k].object_from_world * glm::dvec4(forward, 0.0));
                const std::optional<double> t = raster::first_hit(objects[k].shape, o, d);
                if (!t || *t >= nearest) continue;
                nearest = *t;
                const glm::dvec3 n =
                    glm::normalize(prepared[k].normal_matrix * raster::surface_normal(objects[k].shape, o + *t * d));
                const double intensity = exact_intensity(objects[k].material, lights, n, to_eye);
                const raster::Rgb base = objects[k].material.base;
                colour =
                    raster::Rgb{rounded(base.r * intensity), rounded(base.g * intensity), rounded(base.b * intensity)};
            }
            if (!colour) continue;
            image.colour.set_pixel(i, j, *colour);
            const std::size_t at =
                static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i);
            image.covered[at] = 1;
            image.depth[at] = nearest;
        }
    }
    return image;
}

}  // namespace lab
