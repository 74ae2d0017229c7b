#pragma once

// A raster scene lit in linear light (Phase 2 materials, directional and point lights, textures,
// depth darkening) drawn by GL with a GLSL program doing raster's sums per pixel.
#include "gl_context.hpp"

#include <raster/render/scene.hpp>

#include <map>
#include <string>
#include <vector>

namespace bench {

class GlScene {
public:
    GlScene() = default;
    ~GlScene();
    GlScene(const GlScene&) = delete;
    GlScene& operator=(const GlScene&) = delete;

    // Meshes and textures are uploaded the first time they are drawn and kept.
    void draw(const GlContext& context, const raster::PerspectiveScene& scene);
    void draw(const GlContext& context, const raster::Scene& scene);

private:
    struct Arrays {
        std::vector<float> positions, normals, uvs;
        std::vector<GLuint> indices;
    };
    template <typename Camera>
    void draw_scene(const GlContext& context, const raster::BasicScene<Camera>& scene, bool perspective);
    const Arrays& arrays(const raster::Mesh& mesh);
    GLuint texture(const raster::Texture& texture, raster::Sampler sampler);
    // The program for a mix of lights and material, given as #define lines.
    GLuint program(const std::string& defines);

    std::map<std::string, GLuint> programs_;
    std::map<const raster::Mesh*, Arrays> meshes_;
    std::map<const raster::Texture*, GLuint> textures_;
};

}  // namespace bench
