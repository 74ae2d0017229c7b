// libFuzzer target: the model and texture loading path. Bytes become OBJ and MTL text (read by
// parse_obj whole and in byte ranges, which must agree, then framed and drawn) or an image (decoded, then sampled with
// every filter). Bad input may only ever be a std::runtime_error; nothing may crash, hang or overrun a buffer.
#include <raster/io/obj_file.hpp>
#include <raster/io/texture_file.hpp>
#include <raster/render/model_scene.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

constexpr std::size_t kMaxTexels = 1 << 16;  // small, so the fuzzer spends its time on parsing

void draw(const std::shared_ptr<const raster::Model>& model, raster::ShadingMethod shading) {
    raster::ModelView view;
    view.shading = shading;
    try {
        const raster::ModelStage stage(model, view, 24, 18);
        raster::Framebuffer frame(24, 18);
        raster::DepthBuffer depth;
        stage.render(frame, depth, 0.5);
    } catch (const std::invalid_argument&) {
        // A model too large or too flat to frame is refused, never drawn wrong.
    }
}

void sample_everywhere(const raster::Texture& texture) {
    for (const raster::TextureFilter filter :
         {raster::TextureFilter::nearest, raster::TextureFilter::bilinear, raster::TextureFilter::trilinear}) {
        for (const float u : {-1.5F, 0.0F, 0.3F, 1.0F, 7.25F}) {
            const raster::LinearRgb c =
                texture.sample({u, 1.0F - u}, {{0.1F, 0.0F}, {0.0F, 0.3F}}, {filter, raster::TextureWrap::repeat});
            if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) std::abort();
        }
    }
}

// The bytes of every array of every part, and every warning: two readings that give the same are one model.
std::string fingerprint(const raster::Model& model) {
    std::string bytes;
    const auto add = [&](const auto& values) {
        bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof values[0]);
        bytes += '|';
    };
    for (const raster::ModelPart& part : model.parts) {
        const raster::Mesh& mesh = part.mesh;
        add(mesh.positions), add(mesh.normals), add(mesh.facets), add(mesh.uvs), add(mesh.colours);
        add(mesh.alphas), add(mesh.points), add(mesh.segments), add(mesh.tangents);
        bytes += '#';
    }
    for (const std::string& warning : model.warnings) bytes += warning + "\n";
    return bytes;
}

// The model, or the error, as one reading gives it.
std::string reading(std::string_view obj, std::string_view mtl, const raster::ObjOptions& options) {
    try {
        return fingerprint(raster::parse_obj(obj, mtl, options));
    } catch (const std::runtime_error& error) {
        return std::string("error: ") + error.what();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::span<const std::uint8_t> rest(data + 1, size - 1);
    try {
        if (data[0] % 2 == 0) {
            const raster::Texture texture = raster::decode_texture(rest, kMaxTexels);
            sample_everywhere(texture);
            return 0;
        }
        // OBJ text, then the MTL text after the first NUL byte.
        const std::string_view text(reinterpret_cast<const char*>(rest.data()), rest.size());
        const std::size_t split = text.find('\0');
        const std::string_view obj = text.substr(0, split);
        const std::string_view mtl = split == std::string_view::npos ? std::string_view() : text.substr(split + 1);
        raster::ObjOptions options;
        options.max_line_bytes = 256;  // short enough for the fuzzer to reach the refusal of long lines
        options.threads = 1;
        // Read in byte ranges on three threads, the file must be the model (or the error) it is read whole.
        raster::ObjOptions in_ranges = options;
        in_ranges.threads = 3;
        in_ranges.range_bytes = 1 + data[0] / 4U % 32U;
        if (reading(obj, mtl, options) != reading(obj, mtl, in_ranges)) std::abort();
        const auto model = std::make_shared<const raster::Model>(raster::parse_obj(obj, mtl, options));
        draw(model, data[0] % 4 == 1 ? raster::ShadingMethod::phong : raster::ShadingMethod::unlit);
    } catch (const std::runtime_error&) {
        // The one way bad input may end: a clear error.
    }
    return 0;
}
