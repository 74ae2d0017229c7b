// libFuzzer target: random triangle soups, poses, cameras, materials of both phases and
// directional and point lights through the whole mesh pipeline, orthographic or in perspective
// (vertex stage, clipping, culling, fill, interpolation, depth, every shader). It must never
// crash or write outside its buffers (the sanitizers watch), and its invariants must hold.
#include <raster/rasterize/draw_mesh.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <fuzzer/FuzzedDataProvider.h>

namespace {

constexpr int kWidth = 24, kHeight = 18;

// Mostly ordinary numbers, sometimes huge, tiny, NaN or infinite.
float any_float(FuzzedDataProvider& input) {
    switch (input.ConsumeIntegralInRange(0, 7)) {
    case 0: return input.ConsumeFloatingPoint<float>();
    case 1: return std::numeric_limits<float>::quiet_NaN();
    case 2:
        return input.ConsumeBool() ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
    default: return input.ConsumeFloatingPointInRange(-1.5F, 1.5F);
    }
}

glm::vec3 any_vector(FuzzedDataProvider& input) {
    const float x = any_float(input), y = any_float(input);
    return {x, y, any_float(input)};
}

raster::Mesh soup(FuzzedDataProvider& input) {
    raster::Mesh mesh;
    const int vertices = input.ConsumeIntegralInRange(1, 12);
    for (int i = 0; i < vertices; ++i) {
        mesh.positions.push_back(any_vector(input));
        mesh.normals.push_back(any_vector(input));
    }
    const int facets = input.ConsumeIntegralInRange(0, 16);
    for (int i = 0; i < facets; ++i) {
        const auto corner = [&] {
            return input.ConsumeIntegralInRange<std::uint32_t>(0, static_cast<std::uint32_t>(vertices - 1));
        };
        const std::uint32_t a = corner(), b = corner(), c = corner();
        mesh.facets.push_back({{a, b, c}, any_vector(input)});
    }
    mesh.surface = input.ConsumeBool() ? raster::Surface::smooth : raster::Surface::faceted;
    mesh.convex = input.ConsumeBool();
    return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider input(data, size);
    raster::Scene scene{raster::OrthoCamera(kWidth, kHeight), {1, 2, 3}, {}, {}, {}};
    if (input.ConsumeBool()) {
        try {
            scene.camera =
                raster::OrthoCamera::look_at(kWidth, kHeight, any_vector(input), any_vector(input), any_vector(input));
        } catch (const std::invalid_argument&) {
            return 0;  // a camera refused with a clear error is a fine outcome
        }
    }
    const int lights = input.ConsumeIntegralInRange(0, 3);
    for (int i = 0; i < lights; ++i) scene.lights.push_back({any_vector(input), any_float(input)});
    const int points = input.ConsumeIntegralInRange(0, 2);
    for (int i = 0; i < points; ++i) {
        const glm::vec3 position = any_vector(input);
        const float intensity = any_float(input);
        const float k_c = any_float(input), k_l = any_float(input);
        scene.point_lights.push_back({position, intensity, {k_c, k_l, any_float(input)}});
    }
    const int objects = input.ConsumeIntegralInRange(1, 3);
    for (int i = 0; i < objects; ++i) {
        glm::mat4 model(1.0F);
        for (int k = 0; k < 12 && input.ConsumeBool(); ++k) model[k / 3][k % 3] = any_float(input);
        raster::SurfaceMaterial material;
        if (input.ConsumeBool()) {
            raster::IntensityMaterial phase1{
                {input.ConsumeIntegral<std::uint8_t>(), input.ConsumeIntegral<std::uint8_t>(), 200},
                any_float(input),
                any_float(input),
                {}};
            if (input.ConsumeBool()) phase1.shininess = any_float(input);
            material = phase1;
        } else {
            const auto colour = [&] {
                const float r = any_float(input), g = any_float(input);
                return raster::LinearRgb{r, g, any_float(input)};
            };
            raster::LinearMaterial phase2{colour(), colour(), colour(), {}};
            if (input.ConsumeBool()) phase2.shininess = any_float(input);
            material = phase2;
        }
        const auto method = static_cast<raster::ShadingMethod>(input.ConsumeIntegralInRange(0, 2));
        scene.objects.push_back({std::make_shared<const raster::Mesh>(soup(input)), model, material, method});
    }
    raster::Framebuffer first(kWidth, kHeight), second(kWidth, kHeight);
    raster::DepthBuffer depth;
    // Half the time through a pinhole: clipping at near, far and the guard band, and 1/w.
    const int fov = input.ConsumeBool() ? input.ConsumeIntegralInRange(1, 179) : 0;
    std::optional<raster::PerspectiveScene> pinhole;
    const bool own_lens = fov == 0 && input.ConsumeBool();
    try {
        if (fov != 0) pinhole = raster::in_perspective(scene, kWidth, kHeight, fov);
        if (own_lens) {  // a first-person camera with any lens at all
            const glm::vec3 eye = any_vector(input);
            const double pitch = any_float(input), yaw = any_float(input);
            const raster::PerspectiveCamera::Lens lens{any_float(input) * 100.0, input.ConsumeFloatingPoint<double>(),
                                                       input.ConsumeFloatingPoint<double>()};
            pinhole = raster::PerspectiveScene{
                raster::PerspectiveCamera::first_person(kWidth, kHeight, eye, pitch, yaw, lens), scene.background,
                scene.lights, scene.point_lights, scene.objects};
        }
    } catch (const std::invalid_argument&) {
        return 0;  // a camera refused with a clear error is a fine outcome
    }
    // Now and then more samples: multisampling's own coverage, depth and resolve.
    const int samples =
        input.ConsumeBool() ? raster::kSampleCounts[static_cast<std::size_t>(input.ConsumeIntegralInRange(1, 4))] : 1;
    const auto draw = [&](raster::Framebuffer& image) {
        return pinhole ? raster::render(image, *pinhole, depth, {.samples = samples})
                       : raster::render(image, scene, depth, {.samples = samples});
    };
    const std::size_t drawn = draw(first);
    // Deterministic: the same scene draws the same pixels again, into a buffer that held others.
    second.clear({9, 9, 9});
    if (draw(second) != drawn || !(first == second)) std::abort();
    if (samples > 1) return 0;  // the samples keep their own depths; the checks below are of the depth buffer
    // Depth is prepared exactly when the rule asks for it, and then holds no NaN.
    if (depth.allocated() != raster::needs_depth(scene)) std::abort();
    if (depth.allocated()) {
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (std::isnan(depth.at(x, y))) std::abort();
            }
        }
    }
    return 0;
}
