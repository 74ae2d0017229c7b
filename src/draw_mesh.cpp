#include <raster/draw_mesh.hpp>

#include "shaded_triangle.hpp"

namespace raster {

std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const FlatShader& shader) {
    return detail::draw_facets(target.colour, target.depth, camera, mesh, shader);
}

std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const GouraudShader& shader) {
    return detail::draw_facets(target.colour, target.depth, camera, mesh, shader);
}

std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const PhongShader& shader) {
    return detail::draw_facets(target.colour, target.depth, camera, mesh, shader);
}

}  // namespace raster
