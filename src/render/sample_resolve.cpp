#include "render/sample_resolve.hpp"

#include <raster/image/colour.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raster::detail {

SampleResolve::SampleResolve(int width, int height, bool with_alpha)
    : width_(width), height_(height), with_alpha_(with_alpha),
      sums_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0.0F) {
    if (with_alpha_) covered_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0F);
}

void SampleResolve::add(const Framebuffer& pass, std::span<const std::uint8_t> coverage) {
    if (pass.width() != width_ || pass.height() != height_)
        throw std::invalid_argument("a sample pass differs in size from its frame");
    const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    if (with_alpha_ && coverage.size() != pixels)
        throw std::invalid_argument("a sample pass needs its coverage for a transparent frame");
    const std::uint8_t* bytes = pass.bytes().data();
    const std::array<float, 256>& linear = linear_from_srgb_bytes();
    for (std::size_t i = 0; i < pixels; ++i) {
        float weight = 1.0F;  // a pass's alpha under transparent surfaces may lie between 0 and 255
        if (with_alpha_) {
            if (coverage[i] == 0) continue;
            weight = coverage[i] == 255 ? 1.0F : static_cast<float>(coverage[i]) / 255.0F;
            covered_[i] += weight;
        }
        for (std::size_t c = 0; c < 3; ++c) sums_[i * 3 + c] += linear[bytes[i * 3 + c]] * weight;
    }
    ++passes_;
}

void SampleResolve::resolve(Framebuffer& out, Rgb background, std::vector<std::uint8_t>* alpha) const {
    if (out.width() != width_ || out.height() != height_)
        throw std::invalid_argument("a resolved frame differs in size from its passes");
    const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    if (alpha != nullptr && with_alpha_) alpha->assign(pixels, 255);
    std::uint8_t* bytes = out.pixels();
    for (std::size_t i = 0; i < pixels; ++i) {
        const float count = with_alpha_ ? covered_[i] : static_cast<float>(passes_);
        if (count == 0.0F) {
            bytes[i * 3] = background.r, bytes[i * 3 + 1] = background.g, bytes[i * 3 + 2] = background.b;
        } else {
            const float share = 1.0F / count;
            for (std::size_t c = 0; c < 3; ++c) bytes[i * 3 + c] = srgb_byte_from_linear(sums_[i * 3 + c] * share);
        }
        if (alpha != nullptr && with_alpha_) {
            (*alpha)[i] =
                static_cast<std::uint8_t>(std::lround(255.0 * static_cast<double>(count) / std::max(passes_, 1)));
        }
    }
}

}  // namespace raster::detail
