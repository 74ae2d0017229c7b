#include <raster/rasterize/draw_mesh.hpp>
#include <raster/shade/shaders.hpp>
#include <raster/shade/textured_shaders.hpp>

#include "rasterize/setup_ortho.hpp"

// The rasterizer compiled once per library shader, here where the shaders are known.
namespace raster {

template <Shader S>
std::size_t draw_mesh(RenderTarget target, const OrthoCamera& camera, const Mesh& mesh, const S& shader) {
    return detail::draw_facets(target.colour, target.depth, camera, mesh, shader, {}, target.rows);
}

template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const FlatShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const GouraudShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const PhongShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const LinearFlatShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const LinearGouraudShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const LinearPhongShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const UnlitShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const TexturedFlatShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const TexturedGouraudShader&);
template std::size_t draw_mesh(RenderTarget, const OrthoCamera&, const Mesh&, const TexturedPhongShader&);

}  // namespace raster
