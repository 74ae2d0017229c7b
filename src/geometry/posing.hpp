#pragma once

#include <raster/geometry/mesh.hpp>

#include <cstddef>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

// posed() in pieces, so that a render can pose a big mesh on several threads: ranges of
// vertices and of facets are moved in any order, each element by posed()'s own arithmetic.
namespace raster::detail {

class Posing {
public:
    // Sizes the result; texture coordinates, colours, surface and convexity are copied at once.
    Posing(const Mesh& mesh, const glm::mat4& model, PoseParts parts);
    void vertices(std::size_t begin, std::size_t end) noexcept;
    void facets(std::size_t begin, std::size_t end) noexcept;
    [[nodiscard]] const Mesh& mesh() const noexcept { return result_; }
    [[nodiscard]] Mesh take() && noexcept { return std::move(result_); }

private:
    const Mesh& source_;
    glm::mat4 model_;
    glm::mat3 normal_matrix_;
    bool mirrored_;
    PoseParts parts_;
    Mesh result_;
};

}  // namespace raster::detail
