#include "io/vertex_alpha.hpp"

#include <algorithm>
#include <cmath>

namespace raster::detail {

float vertex_alpha(float written, std::size_t& unreadable) noexcept {
    if (!(written >= 0.0F && written <= 1.0F)) ++unreadable;
    return std::isfinite(written) ? std::clamp(written, 0.0F, 1.0F) : 1.0F;
}

void warn_of_vertex_alphas(const std::string& file, std::size_t unreadable, std::vector<std::string>& warnings) {
    if (unreadable == 0) return;
    warnings.push_back(file + ": clamped " + std::to_string(unreadable) +
                       " vertex alphas outside [0, 1] (one that is not a number reads as 1)");
}

void settle_vertex_alphas(ModelPart& part, bool gltf) noexcept {
    if (part.mesh.alphas.empty() || part.opacity.mode != AlphaMode::opaque) return;
    if (gltf || part.mesh.facets.empty()) {
        part.mesh.alphas = {};
    } else {
        part.opacity.mode = AlphaMode::blend;
    }
}

}  // namespace raster::detail
