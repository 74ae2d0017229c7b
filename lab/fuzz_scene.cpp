// libFuzzer target: glTF 2.0, STL and PLY read as render reads them (read_model: format checks,
// structure checks, then assimp in a child process under limits), then framed and drawn. The
// first byte picks the format; bad input may only ever be a std::runtime_error. Run with
// -detect_leaks=0: assimp 5.2.5 itself leaks on some malformed STL files; CI replays the seeds.
#include <raster/io/model_file.hpp>
#include <raster/render/model_scene.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static constexpr std::array<const char*, 4> kFormats{".stl", ".stl", ".ply", ".gltf"};
    const std::span<const std::uint8_t> rest(data + 1, size - 1);
    std::string ending = kFormats[data[0] % kFormats.size()];
    if (ending == ".gltf" && rest.size() >= 4 &&
        std::string_view(reinterpret_cast<const char*>(rest.data()), 4) == "glTF")
        ending = ".glb";
    // One file per fuzzing process, named by its id: the reader is given a path as render gives it.
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("raster-fuzz-scene-" + std::to_string(::getpid()) + ending);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(rest.data()), static_cast<std::streamsize>(rest.size()));
    try {
        raster::ObjOptions options;
        options.load_textures = false;
        options.confine = std::filesystem::temp_directory_path();
        options.limits.max_seconds = 5.0;  // within libFuzzer's own -timeout=10
        options.limits.max_memory = std::uint64_t{1} << 30;
        const auto model = std::make_shared<const raster::Model>(raster::read_model(path, options));
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
    std::filesystem::remove(path);
    return 0;
}
