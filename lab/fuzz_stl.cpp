// libFuzzer target: raster's own STL reader (parse_stl) in this process, then framed and drawn.
// Bad input may only ever be a std::runtime_error; nothing may crash, hang, overrun a buffer or
// allocate what a triangle count merely claims.
#include <raster/io/stl_file.hpp>
#include <raster/render/model_scene.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto model = std::make_shared<const raster::Model>(raster::parse_stl(std::span(data, size)));
        raster::ModelView view;
        view.shading = size % 2 == 0 ? raster::ShadingMethod::phong : raster::ShadingMethod::unlit;
        const raster::ModelStage stage(model, view, 24, 18);
        raster::Framebuffer frame(24, 18);
        raster::DepthBuffer depth;
        stage.render(frame, depth, 0.5);
    } catch (const std::runtime_error&) {
        // A file raster cannot read: a clear error.
    } catch (const std::invalid_argument&) {
        // A model too large or too flat to frame is refused, never drawn wrong.
    }
    return 0;
}
