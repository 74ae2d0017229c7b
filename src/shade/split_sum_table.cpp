#include <raster/shade/gltf_brdf.hpp>
#include <raster/shade/split_sum_table.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace raster {
namespace {

using gltf_brdf::kPi;

// The i-th of n points of the Hammersley set: evenly spread, no randomness to seed.
glm::vec2 hammersley(unsigned i, unsigned n) noexcept {
    unsigned bits = i;
    bits = (bits << 16U) | (bits >> 16U);
    bits = ((bits & 0x55555555U) << 1U) | ((bits & 0xAAAAAAAAU) >> 1U);
    bits = ((bits & 0x33333333U) << 2U) | ((bits & 0xCCCCCCCCU) >> 2U);
    bits = ((bits & 0x0F0F0F0FU) << 4U) | ((bits & 0xF0F0F0F0U) >> 4U);
    bits = ((bits & 0x00FF00FFU) << 8U) | ((bits & 0xFF00FF00U) >> 8U);
    return {(static_cast<float>(i) + 0.5F) / static_cast<float>(n), static_cast<float>(bits) * 2.3283064365386963e-10F};
}

float node(int i, int size) { return static_cast<float>(i) / static_cast<float>(size - 1); }

// One entry: the split sum's scale and bias, by GGX importance sampling about n = +z.
SplitSumTable::Specular integrate_specular(float n_dot_v, float roughness, unsigned samples) {
    const glm::vec3 v(std::sqrt(1.0F - n_dot_v * n_dot_v), 0.0F, n_dot_v);
    const float alpha = std::max(roughness * roughness, gltf_brdf::kSmallestAlpha);
    double scale = 0.0, bias = 0.0;
    for (unsigned i = 0; i < samples; ++i) {
        const glm::vec2 xi = hammersley(i, samples);
        const float phi = 2.0F * kPi * xi.x;
        const float cos_theta = std::sqrt((1.0F - xi.y) / (1.0F + (alpha * alpha - 1.0F) * xi.y));
        const float sin_theta = std::sqrt(std::max(0.0F, 1.0F - cos_theta * cos_theta));
        const glm::vec3 h(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
        const float v_dot_h = glm::dot(v, h);
        const glm::vec3 l = 2.0F * v_dot_h * h - v;
        if (!(l.z > 0.0F) || !(v_dot_h > 0.0F)) continue;
        // f cos / pdf with pdf(l) = D n.h / (4 v.h): D cancels.
        const float weight = 4.0F * gltf_brdf::visibility(l.z, n_dot_v, alpha) * l.z * v_dot_h / h.z;
        const float m = 1.0F - v_dot_h, fc = m * m * m * m * m;
        scale += (1.0F - fc) * weight;
        bias += fc * weight;
    }
    return {static_cast<float>(scale / samples), static_cast<float>(bias / samples)};
}

// The (1 - Fc)-weighted Lambert lobe's albedo, by cosine sampling (the pdf cancels cos / pi).
float integrate_diffuse(float n_dot_v, unsigned samples) {
    const glm::vec3 v(std::sqrt(1.0F - n_dot_v * n_dot_v), 0.0F, n_dot_v);
    double sum = 0.0;
    for (unsigned i = 0; i < samples; ++i) {
        const glm::vec2 xi = hammersley(i, samples);
        const float r = std::sqrt(xi.y), phi = 2.0F * kPi * xi.x;
        const glm::vec3 l(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0F, 1.0F - xi.y)));
        const float v_dot_h = glm::dot(v, glm::normalize(v + l));
        const float m = 1.0F - v_dot_h;
        sum += 1.0F - m * m * m * m * m;
    }
    return static_cast<float>(sum / samples);
}

}  // namespace

SplitSumTable::SplitSumTable(int size, int samples) : size_(std::max(size, 2)) {
    const auto count = static_cast<unsigned>(std::max(samples, 1));
    const auto cells = static_cast<std::size_t>(size_);
    specular_.reserve(cells * cells);
    diffuse_.reserve(cells);
    // Columns crowd toward grazing (n.v = t^2), where the integrals change fastest; n.v = 0 sees
    // nothing, so its column is taken just above, where they still converge.
    const auto cosine = [&](int i) { return std::max(node(i, size_) * node(i, size_), 1e-3F); };
    for (int r = 0; r < size_; ++r) {
        for (int c = 0; c < size_; ++c) specular_.push_back(integrate_specular(cosine(c), node(r, size_), count));
    }
    for (int c = 0; c < size_; ++c) diffuse_.push_back(integrate_diffuse(cosine(c), count * 4));
}

SplitSumTable::Specular SplitSumTable::specular(float n_dot_v, float roughness) const noexcept {
    const float last = static_cast<float>(size_ - 1);
    const float x = std::sqrt(std::clamp(std::isfinite(n_dot_v) ? n_dot_v : 0.0F, 0.0F, 1.0F)) * last;
    const float y = std::clamp(std::isfinite(roughness) ? roughness : 1.0F, 0.0F, 1.0F) * last;
    const int x0 = std::min(static_cast<int>(x), size_ - 2), y0 = std::min(static_cast<int>(y), size_ - 2);
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    const auto at = [&](int c, int r) { return specular_[static_cast<std::size_t>(r * size_ + c)]; };
    const auto mix = [](Specular a, Specular b, float t) {
        return Specular{a.scale + (b.scale - a.scale) * t, a.bias + (b.bias - a.bias) * t};
    };
    return mix(mix(at(x0, y0), at(x0 + 1, y0), fx), mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

float SplitSumTable::diffuse(float n_dot_v) const noexcept {
    const float x =
        std::sqrt(std::clamp(std::isfinite(n_dot_v) ? n_dot_v : 0.0F, 0.0F, 1.0F)) * static_cast<float>(size_ - 1);
    const int x0 = std::min(static_cast<int>(x), size_ - 2);
    const float fx = x - static_cast<float>(x0);
    const auto at = [&](int c) { return diffuse_[static_cast<std::size_t>(c)]; };
    return at(x0) + (at(x0 + 1) - at(x0)) * fx;
}

}  // namespace raster
