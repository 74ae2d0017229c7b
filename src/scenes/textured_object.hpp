#pragma once

#include <raster/render/scene.hpp>

#include <memory>
#include <optional>
#include <utility>

// How the seed scenes place a textured mesh: grey Phong material, the texture giving the colour.
namespace raster::detail {

[[nodiscard]] inline LinearMaterial textured_material(float diffuse, float specular = 0.0F,
                                                      std::optional<float> shininess = std::nullopt) {
    return {LinearRgb{}, LinearRgb{diffuse, diffuse, diffuse}, LinearRgb{specular, specular, specular}, shininess};
}

[[nodiscard]] inline SceneObject textured_object(Mesh mesh, glm::mat4 model, std::shared_ptr<const Texture> texture,
                                                 LinearMaterial material = textured_material(1.0F)) {
    return {std::make_shared<const Mesh>(std::move(mesh)),
            model,
            material,
            ShadingMethod::phong,
            std::nullopt,
            std::move(texture),
            Sampler{}};
}

}  // namespace raster::detail
