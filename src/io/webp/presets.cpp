#include "io/webp/presets.hpp"

#include <stdexcept>

namespace raster::detail {
namespace {

struct EncoderSettings {
    int method;
    float quality;
    bool minimize_size;
};

EncoderSettings settings_for(Effort effort) {
    switch (effort) {
    case Effort::fast: return {0, 0.0F, true};
    case Effort::balanced: return {4, 50.0F, true};
    case Effort::max: return {6, 100.0F, true};
    }
    throw std::invalid_argument("unknown effort");
}

}  // namespace

WebPConfig lossless_config(Effort effort) {
    WebPConfig config;
    if (!WebPConfigInit(&config)) throw std::runtime_error("libwebp version mismatch");
    const EncoderSettings settings = settings_for(effort);
    config.lossless = 1;
    config.exact = 1;
    config.method = settings.method;
    config.quality = settings.quality;
    return config;
}

// Chosen from the encode lab's Pareto front (doc/performance.md): the changed rectangles are
// small, so a lighter method costs little size.
WebPConfig parallel_config(Effort effort) {
    WebPConfig config = lossless_config(effort);
    if (effort != Effort::max) {  // method 0 and 1 at quality 50: on the front for fast and default
        config.method = effort == Effort::fast ? 0 : 1;
        config.quality = 50.0F;
    }
    return config;
}

bool minimize_size(Effort effort) { return settings_for(effort).minimize_size; }

}  // namespace raster::detail
