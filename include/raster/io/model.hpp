#pragma once

#include <raster/geometry/mesh.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/model_camera.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/metallic_roughness.hpp>
#include <raster/shade/opacity.hpp>
#include <raster/shade/phong_maps.hpp>
#include <raster/shade/texture.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

// A model read from a file: one mesh per material, in raster's world (doc/conventions.md#models).
namespace raster {

struct ModelPart {
    std::string material_name;  // empty for the default material
    Mesh mesh;
    LinearMaterial material;
    std::shared_ptr<const Texture> texture{};  // the diffuse map, when it loaded
    Sampler sampler{};
    Opacity opacity{};       // from MTL d and Tr, glTF alphaMode and base colour alpha
    PhongMaps phong_maps{};  // MTL map_Ks, map_Ke and bump, over `material`
    // A physically based material (glTF's, or an MTL's PBR fields), drawn in place of `material`
    // and `texture` when present (doc/conventions.md#metallic-roughness).
    std::optional<MetallicRoughness> metallic_roughness{};
};

struct Model {
    std::vector<ModelPart> parts;
    // What was read but not used as the file asked, one line each, naming the file.
    std::vector<std::string> warnings;
    // Every file read to make it: the model, its material libraries and textures.
    std::vector<InputRecord> sources;
    // The cameras the file carries, in its own order (glTF's); `render --camera N` draws from one.
    std::vector<ModelCamera> cameras;
};

// Why a model with no faces, points or lines is refused, in every reader's words.
inline constexpr const char* kNothingToDraw = "nothing to draw: no faces, points or lines";

// The material of a model file without one: a light grey, no highlight (Blender's default diffuse).
[[nodiscard]] LinearMaterial default_model_material() noexcept;

[[nodiscard]] std::size_t triangle_count(const Model& model) noexcept;
// Vertices drawn as points, and lines, over every part.
[[nodiscard]] std::size_t point_count(const Model& model) noexcept;
[[nodiscard]] std::size_t segment_count(const Model& model) noexcept;

// For each part, whether it is open: some edge of it is not met as often running one way as the
// other, over the whole model (positions compared exactly, so a closed surface may be split
// into parts). Only a closed part's back faces may be culled unseen.
[[nodiscard]] std::vector<bool> open_parts(const Model& model);
// The mesh with each facet also turned to face the other way, its corners' normals flipped:
// an open surface (a leaf, a plane, a lone triangle) drawn and lit from both sides; the copy's
// tangent frames turned round too, so a normal map's normals are the front's turned round.
[[nodiscard]] Mesh both_sides(const Mesh& mesh);

// The smallest axis-aligned box around every vertex the facets, points and lines use, and the
// smallest sphere about the box's centre that holds them all.
struct Bounds {
    glm::dvec3 low;
    glm::dvec3 high;
    double radius;
    [[nodiscard]] glm::dvec3 centre() const noexcept { return (low + high) * 0.5; }
};
// Throws std::invalid_argument for a model with nothing to draw.
[[nodiscard]] Bounds bounds_of(const Model& model);

}  // namespace raster
