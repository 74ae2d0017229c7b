#pragma once

#include <raster/image/colour.hpp>

#include <cstddef>
#include <vector>

// The environment half of glTF's BRDF, integrated once: for each viewing angle and roughness,
// the scale and bias that turn f0 into the share of uniform surrounding light the specular lobe
// reflects (Karis's split sum), and the share its (1 - F)-weighted Lambert lobe reflects
// (doc/conventions.md#surroundings).
namespace raster {

class SplitSumTable {
public:
    // `size` steps of sqrt(n.v) and of roughness, each entry integrated from `samples` directions
    // (GGX importance sampling for the specular lobe, cosine sampling for the diffuse one).
    explicit SplitSumTable(int size = 32, int samples = 1024);

    struct Specular {
        float scale;  // times f0
        float bias;   // plus this (f90 = 1)
    };
    // Bilinear between entries; n.v and roughness clamped to [0, 1].
    [[nodiscard]] Specular specular(float n_dot_v, float roughness) const noexcept;
    // The albedo of the diffuse lobe under uniform light for c_diff = 1, f0 = 0: times (1 - f0) c_diff.
    [[nodiscard]] float diffuse(float n_dot_v) const noexcept;
    [[nodiscard]] int size() const noexcept { return size_; }

private:
    int size_;
    std::vector<Specular> specular_;  // row = roughness, column = n.v
    std::vector<float> diffuse_;      // by n.v
};

}  // namespace raster
