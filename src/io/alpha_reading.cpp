#include "io/alpha_reading.hpp"

#include <optional>

namespace raster::detail {

float alpha_or(float value, float fallback, const std::string& said, std::vector<std::string>& warnings) {
    const std::optional<float> alpha = readable_alpha(value);
    if (!alpha || *alpha != value) {
        const float taken = alpha.value_or(fallback);
        warnings.push_back(said + " " + std::to_string(value) + ", outside 0 to 1; taking " + std::to_string(taken));
        return taken;
    }
    return *alpha;
}

Opacity blended_by(float alpha, const std::string& said, std::vector<std::string>& warnings) {
    const float taken = alpha_or(alpha, 1.0F, said, warnings);
    if (taken >= 1.0F) return {};
    return {AlphaMode::blend, taken, 0.5F};
}

}  // namespace raster::detail
