// libFuzzer target: raster's own PLY reader (parse_ply) in this process, then framed and drawn.
// Bad input may only ever be a std::runtime_error; nothing may crash, hang, overrun a buffer or
// allocate what a header merely claims. Files only assimp's reader reads are fuzz_scene's.
#include <raster/io/ply_file.hpp>
#include <raster/render/model_scene.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (const std::string_view assimps : {"TextureFile", "material", "tristrips", "texcoord"}) {
        if (text.find(assimps) != std::string_view::npos) return 0;  // handed to assimp, which leaks
    }
    try {
        const auto model = std::make_shared<const raster::Model>(raster::parse_ply(std::span(data, size)));
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
