#pragma once

#include <raster/io/model.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

// STL's separate triangles as the one part raster's scene reader made of them through assimp:
// each kept triangle three vertices of its own, mirrored into raster's world and re-wound, the
// file's normal or else the facet's (doc/conventions.md#stl-reader).
namespace raster::detail {

// A binary STL's colour as assimp read it: channels in [0, 1] as written, before sRGB decoding.
struct StlColour {
    float r = 0.6F, g = 0.6F, b = 0.6F, a = 0.6F;  // assimp's default: light grey, 0.6 alpha
};

class StlMesh {
public:
    explicit StlMesh(double crease_degrees);

    void reserve(std::size_t triangles);
    // Adds a triangle of the file's corners (counter-clockwise from outside) and normal; a
    // triangle of no area is dropped, as every reader drops it. False when a corner is not finite.
    // `colour` is the face's own colour, or null for the mesh's default once any face has one.
    [[nodiscard]] bool add(const std::array<glm::vec3, 3>& corners, glm::vec3 normal, const StlColour* colour);
    // The default colour of faces without their own, for every face once any has one.
    void set_default_colour(StlColour colour) noexcept { default_colour_ = colour; }

    // The one part, its material white or `diffuse`; none when no triangle has area.
    void add_part_to(Model& model, const LinearRgb& diffuse);

private:
    void start_colours();
    void push_colour(const StlColour& colour);

    Mesh mesh_;
    double crease_degrees_;
    float cos_crease_;
    glm::dmat3 normal_matrix_;
    StlColour default_colour_{};
    bool coloured_ = false;
    bool translucent_ = false;  // some vertex alpha below 1
};

}  // namespace raster::detail
