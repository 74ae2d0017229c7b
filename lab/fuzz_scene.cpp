// libFuzzer target: glTF 2.0, STL and PLY read through assimp (parse_scene_file), then framed and
// drawn. The first byte picks the format; bad input may only ever be a std::runtime_error.
// Run with -detect_leaks=0: assimp 5.2.5 itself leaks on some malformed STL files, and after
// minutes of fuzzing frees memory it never allocated; CI replays the seeds only.
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static constexpr std::array<const char*, 4> kFormats{"stl", "stl", "ply", "gltf"};
    const std::span<const std::uint8_t> rest(data + 1, size - 1);
    try {
        const auto model = std::make_shared<const raster::Model>(raster::parse_scene_file(rest, kFormats[data[0] % kFormats.size()]));
        raster::ModelView view;
        view.shading = data[0] % 8 < 4 ? raster::ShadingMethod::phong : raster::ShadingMethod::unlit;
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
