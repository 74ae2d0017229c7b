#include <raster/render/render_style.hpp>

#include <raster/rasterize/line.hpp>

#include "camera/clip_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <glm/geometric.hpp>

namespace raster {

namespace {

// The mean colour of a texture in linear light: its 1 x 1 mip level.
LinearRgb mean_colour(const Texture& texture) {
    const Framebuffer& last = texture.level(texture.level_count() - 1);
    return linear_from_srgb(last.pixel(0, 0));
}

template <typename Camera>
BasicScene<Camera> flattened(BasicScene<Camera> scene) {
    for (SceneObject& object : scene.objects) {
        if (auto* material = std::get_if<LinearMaterial>(&object.material); material != nullptr && object.texture) {
            const LinearRgb mean = mean_colour(*object.texture);
            material->diffuse = {material->diffuse.r * mean.r, material->diffuse.g * mean.g,
                                 material->diffuse.b * mean.b};
        }
        if (auto* material = std::get_if<LinearMaterial>(&object.material)) {  // each map's mean times its factor
            if (object.phong_maps.specular)
                material->specular = material->specular * mean_colour(*object.phong_maps.specular);
            if (object.phong_maps.emissive)
                material->emissive = material->emissive * mean_colour(*object.phong_maps.emissive);
        }
        object.texture = nullptr;
        object.phong_maps = {};
        object.shading = ShadingMethod::flat;
    }
    return scene;
}

Rgb line_colour(const SceneObject& object) {
    if (const auto* material = std::get_if<IntensityMaterial>(&object.material)) return material->base;
    if (const auto* pbr = std::get_if<MetallicRoughness>(&object.material)) {
        const MetallicRoughness usable = pbr->usable();
        const LinearRgb mean = pbr->base_colour_map ? mean_colour(*pbr->base_colour_map) : LinearRgb{1.0F, 1.0F, 1.0F};
        return srgb_from_linear(usable.emissive + usable.base_colour * mean);
    }
    const auto& material = std::get<LinearMaterial>(object.material);
    const LinearRgb mean = object.texture ? mean_colour(*object.texture) : LinearRgb{1.0F, 1.0F, 1.0F};
    const LinearRgb glow =
        object.phong_maps.emissive ? mean_colour(*object.phong_maps.emissive) : LinearRgb{1.0F, 1.0F, 1.0F};
    return srgb_from_linear(LinearRgb{material.emissive.r * glow.r + material.diffuse.r * mean.r,
                                      material.emissive.g * glow.g + material.diffuse.g * mean.g,
                                      material.emissive.b * glow.b + material.diffuse.b * mean.b});
}

// Halves up, as fills and lines round (doc/conventions.md#pixels); the clamp keeps int safe for orthographic ends far
// off.
glm::ivec2 nearest_pixel(glm::dvec2 screen) {
    const auto round = [](double v) {
        return static_cast<int>(std::clamp(std::floor(v + 0.5), -16777216.0, 16777216.0));
    };
    return {round(screen.x), round(screen.y)};
}

// The edges of the facets facing the eye, each through `draw_edge(a, b)` in world space.
template <typename Facing, typename DrawEdge>
std::size_t front_edges(const Mesh& mesh, Facing facing, DrawEdge draw_edge) {
    std::size_t drawn = 0;
    for (const Facet& facet : mesh.facets) {
        const glm::vec3 a = mesh.positions[facet.corners[0]], b = mesh.positions[facet.corners[1]],
                        c = mesh.positions[facet.corners[2]];
        if (!facing(facet.normal, a)) continue;
        draw_edge(a, b);
        draw_edge(b, c);
        draw_edge(c, a);
        ++drawn;
    }
    return drawn;
}

// Clips segment (a, b) in clip space to every plane; false when nothing is left.
bool clip_segment(const detail::ClipPlanes& planes, glm::dvec4& a, glm::dvec4& b) {
    for (const glm::dvec4& plane : planes.planes) {
        const double da = detail::ClipPlanes::distance(plane, a), db = detail::ClipPlanes::distance(plane, b);
        if (std::isnan(da) || std::isnan(db)) return false;  // a corner at NaN has no place to cut
        if (!(da >= 0.0) && !(db >= 0.0)) return false;
        if (da >= 0.0 && db >= 0.0) continue;
        const glm::dvec4 cut = a + (b - a) * (da / (da - db));
        (da < 0.0 ? a : b) = cut;
    }
    return true;
}

}  // namespace

Scene flat_style(Scene scene) { return flattened(std::move(scene)); }
PerspectiveScene flat_style(PerspectiveScene scene) { return flattened(std::move(scene)); }

std::size_t draw_wireframe(Framebuffer& framebuffer, const Scene& scene) {
    framebuffer.clear(scene.background);
    std::size_t drawn = 0;
    const glm::vec3 direction = scene.camera.direction();
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        const Mesh mesh = posed(*object.mesh, object.model, PoseParts{false, true});
        const Rgb colour = line_colour(object);
        drawn += front_edges(
            mesh, [&](glm::vec3 normal, glm::vec3) { return glm::dot(normal, direction) < 0.0F; },
            [&](glm::vec3 a, glm::vec3 b) {
                draw_line(framebuffer, nearest_pixel(scene.camera.screen_from_world(a)),
                          nearest_pixel(scene.camera.screen_from_world(b)), colour);
            });
    }
    return drawn;
}

std::size_t draw_wireframe(Framebuffer& framebuffer, const PerspectiveScene& scene) {
    framebuffer.clear(scene.background);
    std::size_t drawn = 0;
    const glm::vec3 eye = scene.camera.eye();
    const detail::ClipPlanes planes(framebuffer.width(), framebuffer.height());
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        const Mesh mesh = posed(*object.mesh, object.model, PoseParts{false, true});
        const Rgb colour = line_colour(object);
        drawn += front_edges(
            mesh, [&](glm::vec3 normal, glm::vec3 corner) { return glm::dot(normal, corner - eye) < 0.0F; },
            [&](glm::vec3 a, glm::vec3 b) {
                glm::dvec4 from = scene.camera.clip_from_world(a), to = scene.camera.clip_from_world(b);
                if (!clip_segment(planes, from, to)) return;
                draw_line(framebuffer, nearest_pixel(scene.camera.screen_from_clip(from)),
                          nearest_pixel(scene.camera.screen_from_clip(to)), colour);
            });
    }
    return drawn;
}

}  // namespace raster
