// material-lab: glTF's metallic-roughness as raster shades it, against the BRDF integrated in
// double precision: a directional light at many angles, and the white furnace (uniform white
// surroundings) for each way of approximating the environment's half of the split sum, with the
// cost of each. Writes material.csv and material-summary.md; lab/material_chart.gp draws the chart.
#include "lab_args.hpp"

#include <raster/geometry/mesh.hpp>
#include <raster/shade/gltf_brdf.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/metallic_roughness_lighting.hpp>
#include <raster/shade/split_sum_table.hpp>
#include <raster/shade/surroundings.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kPi = 3.14159265358979323846;

struct Case {
    double metallic, roughness, n_dot_v;
};

// Appendix B in double, written again from the specification: the reference's BRDF (red channel
// of a white base colour), v in the xz plane about n = +z.
double brdf(const Case& c, double lx, double ly, double lz) {
    const double vx = std::sqrt(1.0 - c.n_dot_v * c.n_dot_v), vz = c.n_dot_v;
    if (lz <= 0.0) return 0.0;
    double hx = lx + vx, hy = ly, hz = lz + vz;
    const double length = std::sqrt(hx * hx + hy * hy + hz * hz);
    hx /= length, hy /= length, hz /= length;
    const double alpha = std::max(c.roughness * c.roughness, 1e-3), a2 = alpha * alpha;
    const double v_dot_h = vx * hx + vz * hz;
    const double f0 = 0.04 * (1.0 - c.metallic) + c.metallic;
    const double f = f0 + (1.0 - f0) * std::pow(1.0 - v_dot_h, 5.0);
    const double d_den = hz * hz * (a2 - 1.0) + 1.0;
    const double d = a2 / (kPi * d_den * d_den);
    const double vis = 0.5 / (lz * std::sqrt(vz * vz * (1.0 - a2) + a2) + vz * std::sqrt(lz * lz * (1.0 - a2) + a2));
    return (1.0 - f) * (1.0 - c.metallic) / kPi + f * d * vis;
}

// The white furnace's reference: the BRDF times cos integrated over the hemisphere, on a grid of
// half vectors crowded toward the normal (theta_h = t^2 pi / 2) so that sharp lobes are resolved.
double furnace(const Case& c) {
    constexpr int kTheta = 1500, kPhi = 360;
    const double vx = std::sqrt(1.0 - c.n_dot_v * c.n_dot_v), vz = c.n_dot_v;
    double sum = 0.0;
    for (int i = 0; i < kTheta; ++i) {
        const double t = (i + 0.5) / kTheta, theta = t * t * kPi / 2.0, d_theta = 2.0 * t * kPi / 2.0 / kTheta;
        for (int j = 0; j < kPhi; ++j) {
            const double phi = (j + 0.5) / kPhi * 2.0 * kPi;
            const double hx = std::sin(theta) * std::cos(phi), hy = std::sin(theta) * std::sin(phi),
                         hz = std::cos(theta);
            const double v_dot_h = vx * hx + vz * hz;
            if (v_dot_h <= 0.0) continue;
            const double lx = 2.0 * v_dot_h * hx - vx, ly = 2.0 * v_dot_h * hy, lz = 2.0 * v_dot_h * hz - vz;
            // dl = 4 (v.h) dh, dh = sin(theta) dtheta dphi
            sum += brdf(c, lx, ly, lz) * lz * 4.0 * v_dot_h * std::sin(theta) * d_theta * (2.0 * kPi / kPhi);
        }
    }
    return sum;
}

// Karis's analytic fit of the split sum for mobile ("Physically Based Shading on Mobile", 2014).
raster::SplitSumTable::Specular karis_mobile(float n_dot_v, float roughness) {
    const float r0 = roughness * -1.0F + 1.0F, r1 = roughness * -0.0275F + 0.0425F;
    const float r2 = roughness * -0.572F + 1.04F, r3 = roughness * 0.022F - 0.04F;
    const float a004 = std::min(r0 * r0, std::exp2(-9.28F * n_dot_v)) * r0 + r1;
    return {a004 * -1.04F + r2, a004 * 1.04F + r3};
}

struct Method {
    std::string name;
    double setup_ms;
    std::function<float(const Case&)> reflected;  // under uniform white light
};

double nanoseconds_per_call(const Method& m, const std::vector<Case>& cases) {
    volatile float sink = 0.0F;
    const auto start = Clock::now();
    constexpr int kRounds = 200;
    for (int r = 0; r < kRounds; ++r) {
        for (const Case& c : cases) sink = sink + m.reflected(c);
    }
    return std::chrono::duration<double, std::nano>(Clock::now() - start).count() /
           (kRounds * static_cast<double>(cases.size()));
}

}  // namespace

int main(int argc, char** argv) {
    const auto out = lab::out_dir(argc, argv, "material-lab");
    if (!out) return 2;
    std::vector<Case> cases;
    for (const double metallic : {0.0, 0.5, 1.0}) {
        for (int r = 2; r <= 20; r += 2) {
            for (int v = 1; v <= 10; ++v) cases.push_back({metallic, r / 20.0, v / 10.0});
        }
    }
    std::vector<double> reference;
    for (const Case& c : cases) reference.push_back(furnace(c));

    // The directional light: the product's shading (BRDF x pi x intensity x n.l) against pi x the double BRDF.
    double worst_directional = 0.0;
    for (const Case& c : cases) {
        raster::MetallicRoughness m;
        m.metallic = static_cast<float>(c.metallic), m.roughness = static_cast<float>(c.roughness);
        const glm::vec3 v(std::sqrt(1.0F - static_cast<float>(c.n_dot_v * c.n_dot_v)), 0.0F,
                          static_cast<float>(c.n_dot_v));
        for (int k = 0; k < 16; ++k) {
            const double angle = (k + 0.5) / 16.0 * kPi / 2.0, lx = -std::sin(angle), lz = std::cos(angle);
            const std::vector<raster::DirectionalLight> sun{{glm::vec3(lx, 0.0, lz), 1.0F}};
            const raster::MetallicRoughnessLighting lighting(m, {}, nullptr, sun, {}, v);
            const float ours = lighting.shade(raster::MaterialPoint{{0, 0, 0}, {0, 0, 1}}).r;
            const double exact = kPi * brdf(c, lx, 0.0, lz) * lz;
            worst_directional = std::max(worst_directional, std::abs(ours - exact) / std::max(exact, 1e-3));
        }
    }

    const auto timed_table = [](int size, int samples) {
        const auto start = Clock::now();
        auto table = std::make_shared<raster::SplitSumTable>(size, samples);
        return std::pair{table, std::chrono::duration<double, std::milli>(Clock::now() - start).count()};
    };
    std::vector<Method> methods;
    for (const auto& [size, samples] :
         {std::pair{16, 32}, std::pair{32, 64}, std::pair{32, 256}, std::pair{32, 1024}, std::pair{64, 1024}}) {
        const auto [table, ms] = timed_table(size, samples);
        const std::string name = "split sum " + std::to_string(size) + "^2 x " + std::to_string(samples) +
                                 (size == 32 && samples == 1024 ? " (raster)" : "");
        methods.push_back({name, ms, [table](const Case& c) {
                               const auto s =
                                   table->specular(static_cast<float>(c.n_dot_v), static_cast<float>(c.roughness));
                               const float f0 =
                                   0.04F * (1.0F - static_cast<float>(c.metallic)) + static_cast<float>(c.metallic);
                               return f0 * s.scale + s.bias +
                                      (1.0F - f0) * (1.0F - static_cast<float>(c.metallic)) *
                                          table->diffuse(static_cast<float>(c.n_dot_v));
                           }});
    }
    const auto [table, ms] = timed_table(32, 1024);
    methods.push_back({"split sum, diffuse without 1 - F", ms, [table](const Case& c) {
                           const auto s =
                               table->specular(static_cast<float>(c.n_dot_v), static_cast<float>(c.roughness));
                           const float f0 =
                               0.04F * (1.0F - static_cast<float>(c.metallic)) + static_cast<float>(c.metallic);
                           return f0 * s.scale + s.bias + (1.0F - static_cast<float>(c.metallic));
                       }});
    methods.push_back({"Karis mobile fit, diffuse 1 - F(n.v)", 0.0, [](const Case& c) {
                           const auto s = karis_mobile(static_cast<float>(c.n_dot_v), static_cast<float>(c.roughness));
                           const float f0 =
                               0.04F * (1.0F - static_cast<float>(c.metallic)) + static_cast<float>(c.metallic);
                           const float fresnel =
                               f0 + (1.0F - f0) * std::pow(1.0F - static_cast<float>(c.n_dot_v), 5.0F);
                           return f0 * s.scale + s.bias + (1.0F - fresnel) * (1.0F - static_cast<float>(c.metallic));
                       }});

    const auto start = Clock::now();
    const raster::Surroundings studio = raster::Surroundings::studio();
    const double studio_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    // A pixel's cost: the whole shading (two lights and the studio) against Phong's, one pixel at a time.
    const std::vector<raster::DirectionalLight> lights{{{-1, 1, -1}, 0.85F}, {{1, 0.3F, -0.5F}, 0.3F}};
    const raster::MetallicRoughnessLighting pbr(raster::MetallicRoughness{}, {}, &studio, lights, {}, {0, 0, -1});
    const raster::LinearLighting phong({{}, {0.8F, 0.8F, 0.8F}, {0.2F, 0.2F, 0.2F}, 32.0F}, lights, {}, {0, 0, -1});
    const auto per_pixel = [](const auto& shade) {
        volatile float sink = 0.0F;
        const auto begin = Clock::now();
        constexpr int kPixels = 400000;
        for (int i = 0; i < kPixels; ++i) {
            const float a = static_cast<float>(i) * 1e-5F;
            sink = sink + shade(glm::vec3(std::sin(a), std::cos(a) * 0.5F, -0.7F)).r;
        }
        return std::chrono::duration<double, std::nano>(Clock::now() - begin).count() / kPixels;
    };
    const double pbr_ns = per_pixel([&](glm::vec3 n) { return pbr.shade(raster::MaterialPoint{{0, 0, 0}, n}); });
    const double phong_ns = per_pixel([&](glm::vec3 n) { return phong.shade({0, 0, 0}, raster::unit_or_zero(n)); });

    std::ofstream csv(*out / "material.csv");
    csv << "method,nanoseconds per pixel,mean error % of energy,worst error % of energy,setup ms\n";
    std::ofstream md(*out / "material-summary.md");
    md << "# Metallic-roughness against the integrated BRDF\n\n"
       << "White furnace over " << cases.size() << " cases (metallic 0, 0.5, 1; roughness 0.1-1; n.v 0.1-1), "
       << "reference integrated in double on 1500 x 360 half vectors. Directional light: worst relative error "
       << worst_directional * 100.0 << " % over 16 light angles per case. Studio surroundings prefiltered in "
       << studio_ms << " ms. A pixel of metallic-roughness (two lights and the studio, one pixel at a time) costs "
       << pbr_ns << " ns against Phong's " << phong_ns
       << " ns (scalar, without its SIMD lanes).\n\n| method | ns per pixel | mean error, % of energy | worst, % | setup ms |\n|---|---|---|---|---|\n";
    for (const Method& m : methods) {
        double sum = 0.0, worst = 0.0;
        Case worst_case{};
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const double error = std::abs(m.reflected(cases[i]) - reference[i]);
            sum += error;
            if (error > worst) worst = error, worst_case = cases[i];
        }
        std::cout << "  worst at metallic " << worst_case.metallic << ", roughness " << worst_case.roughness << ", n.v "
                  << worst_case.n_dot_v << '\n';
        const double ns = nanoseconds_per_call(m, cases), mean = sum / static_cast<double>(cases.size());
        csv << '"' << m.name << "\"," << ns << ',' << mean * 100.0 << ',' << worst * 100.0 << ',' << m.setup_ms << '\n';
        md << "| " << m.name << " | " << ns << " | " << mean * 100.0 << " | " << worst * 100.0 << " | " << m.setup_ms
           << " |\n";
        std::cout << m.name << ": mean " << mean * 100.0 << " %, worst " << worst * 100.0 << " %, " << ns << " ns\n";
    }
    std::cout << "directional worst relative error " << worst_directional * 100.0 << " %, studio " << studio_ms
              << " ms, pixel " << pbr_ns << " ns (Phong " << phong_ns << " ns)\n";
    return 0;
}
