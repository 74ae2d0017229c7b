#pragma once

#include <raster/render/scene.hpp>
#include <raster/shade/mapped_phong_shader.hpp>
#include <raster/shade/metallic_roughness_shaders.hpp>
#include <raster/shade/shaders.hpp>
#include <raster/shade/textured_shaders.hpp>

#include "render/vertex_alpha_shader.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>

// Which of the library's shaders draws an object: chosen by its material, shading method,
// texture and vertex colours.
namespace raster::detail {

// The surroundings a frame's metallic-roughness objects reflect: the scene's, else the built-in
// studio prefiltered once for the frame; none when no object needs them.
template <typename Camera>
std::shared_ptr<const Surroundings> surroundings_for(const BasicScene<Camera>& scene) {
    if (scene.surroundings) return scene.surroundings;
    const bool needed = std::any_of(scene.objects.begin(), scene.objects.end(), [](const SceneObject& object) {
        return object.mesh && std::holds_alternative<MetallicRoughness>(object.material);
    });
    return needed ? std::make_shared<const Surroundings>(Surroundings::studio()) : nullptr;
}

// Whether the object's vertex alphas count: they multiply a blended or masked material's alpha, as
// its vertex colours multiply its colour, and an intensity material takes neither (doc/conventions.md#vertex-alpha).
inline bool takes_vertex_alpha(const SceneObject& object) noexcept {
    return object.mesh && !object.mesh->alphas.empty() && object.opacity.mode != AlphaMode::opaque &&
           !std::holds_alternative<IntensityMaterial>(object.material);
}

// Lights one object by its material and hands `draw` the shader its shading method asks for.
// `eye` is the viewer's position in perspective; orthographic views have `to_eye` alone.
template <typename Draw>
std::size_t draw_shaded(const SceneObject& object, std::span<const DirectionalLight> lights,
                        std::span<const PointLight> points, glm::vec3 to_eye, std::optional<glm::vec3> eye,
                        std::optional<DepthDarkening> darkening, const Surroundings* surroundings, Draw draw) {
    // A shader that takes vertex colours carries the vertex alpha beside them where it counts.
    const bool vertex_alpha = takes_vertex_alpha(object);
    const auto tinted = [&](const auto& shader) -> std::size_t {
        if (vertex_alpha) return draw(VertexAlphaShader<std::remove_cvref_t<decltype(shader)>>{shader});
        return draw(shader);
    };
    const bool coloured = !object.mesh->colours.empty() || vertex_alpha;
    if (const auto* pbr = std::get_if<MetallicRoughness>(&object.material)) {
        // Shaded per pixel whatever the method asks, but flat takes the facet's normal; unlit draws the base colour.
        if (object.shading == ShadingMethod::unlit) {
            const DiffuseSource base{pbr->usable().base_colour, pbr->base_colour_map.get(), object.sampler,
                                     pbr->base_colour_transform};
            if (coloured) return tinted(TintedUnlitShader{base});
            return draw(UnlitShader{base});
        }
        const MetallicRoughnessLighting lighting(*pbr, object.sampler, surroundings, lights, points, to_eye, eye);
        if (object.shading == ShadingMethod::flat) return tinted(MetallicRoughnessFlatShader{&lighting});
        return tinted(MetallicRoughnessPhongShader{&lighting});
    }
    if (const auto* intensity = std::get_if<IntensityMaterial>(&object.material)) {
        // The intensity model has one viewer direction, the camera's, even in perspective.
        const IntensityLighting lighting(*intensity, lights, to_eye);
        switch (object.shading) {
        case ShadingMethod::flat: return draw(FlatShader{&lighting});
        case ShadingMethod::gouraud: return draw(GouraudShader{&lighting});
        case ShadingMethod::phong: return draw(PhongShader{&lighting});
        case ShadingMethod::unlit: return draw(UnlitShader{{linear_from_srgb(intensity->base)}});
        }
        return 0;
    }
    const LinearMaterial& material = std::get<LinearMaterial>(object.material);
    const LinearLighting lighting(material, lights, points, to_eye, eye, darkening);
    const DiffuseSource diffuse{material.diffuse, object.texture.get(), object.sampler};
    if (object.phong_maps.any() && object.shading != ShadingMethod::unlit) {  // lit at every pixel
        if (object.shading == ShadingMethod::flat)
            return tinted(MappedPhongFlatShader{&lighting, diffuse, &object.phong_maps});
        return tinted(MappedPhongSmoothShader{&lighting, diffuse, &object.phong_maps});
    }
    if (coloured) {  // the corners' colours (and alphas) interpolated to every pixel
        switch (object.shading) {
        case ShadingMethod::flat: return tinted(TintedFlatShader{&lighting, diffuse});
        case ShadingMethod::gouraud: return tinted(TintedGouraudShader{&lighting, diffuse});
        case ShadingMethod::unlit: return tinted(TintedUnlitShader{diffuse});
        default: return tinted(TintedPhongShader{&lighting, diffuse});
        }
    }
    if (object.shading == ShadingMethod::unlit) return draw(UnlitShader{diffuse});
    if (object.texture) {  // the textured shaders read the texture at every pixel
        switch (object.shading) {
        case ShadingMethod::flat: return draw(TexturedFlatShader{&lighting, diffuse});
        case ShadingMethod::gouraud: return draw(TexturedGouraudShader{&lighting, diffuse});
        default: return draw(TexturedPhongShader{&lighting, diffuse});
        }
    }
    switch (object.shading) {
    case ShadingMethod::flat: return draw(LinearFlatShader{&lighting});
    case ShadingMethod::gouraud: return draw(LinearGouraudShader{&lighting});
    default: return draw(LinearPhongShader{&lighting});
    }
}

}  // namespace raster::detail
