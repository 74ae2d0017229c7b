#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace raster {

// One side of the cube: four corner indices, clockwise seen from outside, and its outward
// unit normal (doc/conventions.md#winding).
struct Face {
    std::array<std::size_t, 4> corners;
    glm::vec3 normal;
};

// An edge between two corners, smaller index first.
struct Edge {
    std::size_t from;
    std::size_t to;

    friend constexpr bool operator==(Edge, Edge) = default;
};

// Face slots, in the order faces() lists them and palettes colour them.
enum FaceSlot : std::size_t { kNearFace, kFarFace, kRightFace, kLeftFace, kTopFace, kBottomFace };

// A cube as eight corners and six faces. Made as the unit cube (edge 1, centred at the origin);
// posed() moves it with a model matrix.
class Cube {
public:
    Cube();

    // The cube moved by `model`; normals follow the inverse transpose so scaling keeps them true.
    [[nodiscard]] Cube posed(const glm::mat4& model) const;

    [[nodiscard]] const std::array<glm::vec3, 8>& corners() const noexcept { return corners_; }
    [[nodiscard]] const std::array<Face, 6>& faces() const noexcept { return faces_; }

    // All twelve edges.
    [[nodiscard]] std::vector<Edge> edges() const;
    // Edges of the faces in `slots`, each listed once.
    [[nodiscard]] std::vector<Edge> edges_of(std::span<const std::size_t> slots) const;

private:
    std::array<glm::vec3, 8> corners_;
    std::array<Face, 6> faces_;
};

}  // namespace raster
