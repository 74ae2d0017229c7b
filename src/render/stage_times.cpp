#include <raster/render/stage_times.hpp>

#include <algorithm>

namespace raster {

double estimated_one_core_share(double wall, double processor, int threads) noexcept {
    if (!(wall > 0.0)) return 0.0;
    if (threads <= 1) return 1.0;
    const double t = static_cast<double>(threads);
    const double share = (t * wall - processor) / ((t - 1.0) * wall);
    return std::clamp(share, 0.0, 1.0);
}

double one_core_share(const StageTime& stage, int threads) noexcept {
    if (!stage.counted) return estimated_one_core_share(stage.spent.wall, stage.spent.processor, threads);
    return stage.spent.wall > 0.0 ? std::clamp(stage.one_core / stage.spent.wall, 0.0, 1.0) : 0.0;
}

}  // namespace raster
