#pragma once

#include <raster/geometry/mesh.hpp>

#include <cstddef>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

// posed() in pieces, so that a render can pose a big mesh on several threads: ranges of
// vertices and of facets are moved in any order, each element by posed()'s own arithmetic.
namespace raster::detail {

// One vertex moved by a model matrix, by posed()'s arithmetic: what a render that needs only a
// few of a mesh's vertices at a time (points, lines) uses instead of a posed copy.
class VertexPose {
public:
    explicit VertexPose(const glm::mat4& model) noexcept
        : model_(model), normal_matrix_(glm::transpose(glm::inverse(glm::mat3(model)))) {}
    [[nodiscard]] glm::vec3 position(glm::vec3 p) const noexcept { return glm::vec3(model_ * glm::vec4(p, 1.0F)); }
    [[nodiscard]] glm::vec3 normal(glm::vec3 n) const noexcept { return unit_or_zero(normal_matrix_ * n); }
    // A direction in the surface; a mirror turns its handedness.
    [[nodiscard]] glm::vec4 tangent(glm::vec4 t, bool mirrored) const noexcept {
        return glm::vec4(unit_or_zero(glm::mat3(model_) * glm::vec3(t)), mirrored ? -t.w : t.w);
    }

private:
    glm::mat4 model_;
    glm::mat3 normal_matrix_;
};

class Posing {
public:
    // Sizes the result; texture coordinates, colours, alphas, surface and convexity are copied at once.
    Posing(const Mesh& mesh, const glm::mat4& model, PoseParts parts);
    void vertices(std::size_t begin, std::size_t end) noexcept;
    void facets(std::size_t begin, std::size_t end) noexcept;
    [[nodiscard]] const Mesh& mesh() const noexcept { return result_; }
    [[nodiscard]] Mesh take() && noexcept { return std::move(result_); }

private:
    const Mesh& source_;
    VertexPose pose_;
    bool mirrored_;
    PoseParts parts_;
    Mesh result_;
};

}  // namespace raster::detail
