// texture-lab: texture filters on a checkerboard floor receding to the horizon, each against a
// heavily supersampled ray-cast reference (aliasing error per image band) and timed.
// Writes texture-filtering.csv and texture-summary.md; lab/texture_chart.gp draws the chart.
#include "lab_args.hpp"

#include "rasterize/setup_perspective.hpp"

#include <raster/shade/texture.hpp>
#include <raster/shade/textured_shaders.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 640, kHeight = 360, kBands = 12;
constexpr int kSamples = 16;                   // per side of a pixel: 256 rays each for the reference
constexpr double kFov = 60.0, kPitch = -0.12;  // radians: a little below the horizon
constexpr float kFar = 2000.0F;
constexpr int kSquareTexels = 32;  // texels per checker square; the texture holds 2 x 2 squares

const raster::LinearRgb kLight{0.85F, 0.75F, 0.2F}, kDark{0.02F, 0.05F, 0.3F};

// One checker square per world unit: texture coordinates are world x and z over 2.
raster::Mesh floor_mesh() {
    raster::Mesh mesh;
    mesh.positions = {{-kFar, 0, 0.01F}, {kFar, 0, 0.01F}, {kFar, 0, kFar}, {-kFar, 0, kFar}};
    mesh.normals.assign(4, glm::vec3(0, 1, 0));
    for (const glm::vec3& p : mesh.positions) mesh.uvs.emplace_back(p.x / 2.0F, p.z / 2.0F);
    mesh.facets.push_back(raster::facet_facing_away(mesh.positions, 0, 1, 2, {0, -1, 0}));
    mesh.facets.push_back(raster::facet_facing_away(mesh.positions, 0, 2, 3, {0, -1, 0}));
    return mesh;
}

raster::Texture checker_texture() {
    raster::Framebuffer image(2 * kSquareTexels, 2 * kSquareTexels);
    const raster::Rgb light = raster::srgb_from_linear(kLight), dark = raster::srgb_from_linear(kDark);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x)
            image.set_pixel(x, y, ((x / kSquareTexels + y / kSquareTexels) % 2 == 0) ? light : dark);
    }
    return raster::Texture(image);
}

raster::PerspectiveCamera camera() {
    return raster::PerspectiveCamera::first_person(kWidth, kHeight, {0.0F, 1.0F, 0.0F}, kPitch, 0.0,
                                                   {kFov, 0.01, 4000.0});
}

// The exact picture: each pixel the mean, in linear light, of kSamples^2 rays meeting the floor,
// each ray taking the texel its hit point lies in (the texture as a function, unfiltered).
raster::Framebuffer reference() {
    const raster::Texture texture = checker_texture();
    const raster::Sampler exact{raster::TextureFilter::nearest, raster::TextureWrap::repeat};
    raster::Framebuffer image(kWidth, kHeight);
    const double t = std::tan(kFov * 3.14159265358979 / 360.0), aspect = static_cast<double>(kWidth) / kHeight;
    const glm::dvec3 forward(0.0, std::sin(kPitch), std::cos(kPitch)), up(0.0, std::cos(kPitch), -std::sin(kPitch)),
        right(1, 0, 0);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            raster::LinearRgb sum;
            for (int j = 0; j < kSamples; ++j) {
                for (int i = 0; i < kSamples; ++i) {
                    // Pixel x covers [x - 1/2, x + 1/2); GL's viewport adds the 1/2 back.
                    const double sx = x + (i + 0.5) / kSamples, sy = y + (j + 0.5) / kSamples;
                    const double ndc_x = sx * 2.0 / kWidth - 1.0, ndc_y = 1.0 - sy * 2.0 / kHeight;
                    const glm::dvec3 ray = forward + right * (ndc_x * aspect * t) + up * (ndc_y * t);
                    if (ray.y >= 0.0) continue;  // above the horizon: the black background
                    const double distance = -1.0 / ray.y;
                    const double wx = ray.x * distance, wz = ray.z * distance;
                    if (wz < 0.01 || wz > kFar || std::abs(wx) > kFar) continue;
                    sum = sum + texture.sample({static_cast<float>(wx / 2.0), static_cast<float>(wz / 2.0)}, {}, exact);
                }
            }
            image.set_pixel(x, y, raster::srgb_from_linear(sum * (1.0F / (kSamples * kSamples))));
        }
    }
    return image;
}

struct Row {
    std::string filter;
    std::vector<double> band_rms;  // sRGB byte error, top band (horizon) first
    double rms;
    double ms;
};

Row measure(const std::string& name, raster::TextureFilter filter, const raster::Framebuffer& truth) {
    const raster::Texture texture = checker_texture();
    const raster::Mesh mesh = floor_mesh();
    const raster::UnlitShader shader{{raster::LinearRgb{1, 1, 1}, &texture, {filter, raster::TextureWrap::repeat}}};
    raster::Framebuffer frame(kWidth, kHeight);
    std::vector<double> times;
    for (int k = 0; k < 15; ++k) {
        frame.clear({0, 0, 0});
        const auto start = std::chrono::steady_clock::now();
        raster::detail::draw_facets_in_perspective(frame, nullptr, camera(), mesh, shader);
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    Row row{name, std::vector<double>(kBands, 0.0), 0.0, lab::median(times)};
    std::vector<double> counts(kBands, 0.0);
    double total = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const raster::Rgb a = frame.pixel(x, y), b = truth.pixel(x, y);
            const double d = (std::pow(a.r - b.r, 2) + std::pow(a.g - b.g, 2) + std::pow(a.b - b.b, 2)) / 3.0;
            row.band_rms[static_cast<std::size_t>(y * kBands / kHeight)] += d;
            counts[static_cast<std::size_t>(y * kBands / kHeight)] += 1.0;
            total += d;
        }
    }
    for (int k = 0; k < kBands; ++k)
        row.band_rms[static_cast<std::size_t>(k)] =
            std::sqrt(row.band_rms[static_cast<std::size_t>(k)] / counts[static_cast<std::size_t>(k)]);
    row.rms = std::sqrt(total / (kWidth * kHeight));
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    const std::optional<std::filesystem::path> chosen = lab::out_dir(argc, argv, "texture-lab");
    if (!chosen) return 2;
    const std::filesystem::path out = *chosen;
    std::filesystem::create_directories(out);
    std::cerr << "texture-lab: reference (" << kSamples * kSamples << " rays a pixel)\n";
    const raster::Framebuffer truth = reference();
    std::vector<Row> rows;
    for (const auto& [name, filter] :
         {std::pair{"nearest", raster::TextureFilter::nearest}, std::pair{"bilinear", raster::TextureFilter::bilinear},
          std::pair{"trilinear", raster::TextureFilter::trilinear}}) {
        rows.push_back(measure(name, filter, truth));
    }
    std::ofstream csv(out / "texture-filtering.csv");
    csv << "band";
    for (const Row& r : rows) csv << ',' << r.filter;
    csv << '\n';
    for (int k = 0; k < kBands; ++k) {
        csv << k + 1;
        for (const Row& r : rows) csv << ',' << r.band_rms[static_cast<std::size_t>(k)];
        csv << '\n';
    }
    std::ofstream summary(out / "texture-summary.md");
    summary << "| filter | RMS error, sRGB levels | worst band | ms per " << kWidth << " x " << kHeight
            << " frame (median of 15) |\n|---|---|---|---|\n";
    for (const Row& r : rows) {
        char line[160];
        std::snprintf(line, sizeof line, "| %s | %.2f | %.2f | %.2f |\n", r.filter.c_str(), r.rms,
                      *std::max_element(r.band_rms.begin(), r.band_rms.end()), r.ms);
        summary << line;
    }
    std::cerr << "texture-lab: wrote texture-filtering.csv and texture-summary.md in " << out.string() << "\n";
    return 0;
}
