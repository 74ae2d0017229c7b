#include <raster/rasterize/draw_mesh.hpp>

#include "rasterize/shaded_triangle.hpp"

namespace raster {
namespace {

template <typename Shader>
std::size_t draw(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const Shader& shader) {
    return detail::draw_facets(target.colour, target.depth, camera, mesh, shader, {}, target.rows);
}

}  // namespace

// One instance of the rasterizer per shader, each compiled here once.
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const FlatShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const GouraudShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const PhongShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const LinearFlatShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const LinearGouraudShader& s) {
    return draw(t, c, m, s);
}
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const LinearPhongShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const UnlitShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const TexturedFlatShader& s) { return draw(t, c, m, s); }
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const TexturedGouraudShader& s) {
    return draw(t, c, m, s);
}
std::size_t draw_mesh(RenderTarget t, const OrthoCamera& c, const Mesh& m, const TexturedPhongShader& s) { return draw(t, c, m, s); }

}  // namespace raster
