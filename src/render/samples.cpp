#include <raster/render/samples.hpp>

#include <array>
#include <stdexcept>
#include <string>

namespace raster {

namespace {

// Positions in sixteenths of a pixel, as the Direct3D 11 specification tabulates them.
constexpr glm::vec2 sixteenths(float x, float y) { return {x / 16.0F, y / 16.0F}; }

constexpr std::array<glm::vec2, 1> kOne{sixteenths(0, 0)};
constexpr std::array<glm::vec2, 2> kTwo{sixteenths(4, 4), sixteenths(-4, -4)};
constexpr std::array<glm::vec2, 4> kFour{sixteenths(-2, -6), sixteenths(6, -2), sixteenths(-6, 2), sixteenths(2, 6)};
constexpr std::array<glm::vec2, 8> kEight{sixteenths(1, -3), sixteenths(-1, 3),  sixteenths(5, 1), sixteenths(-3, -5),
                                          sixteenths(-5, 5), sixteenths(-7, -1), sixteenths(3, 7), sixteenths(7, -7)};
constexpr std::array<glm::vec2, 16> kSixteen{
    sixteenths(1, 1),  sixteenths(-1, -3), sixteenths(-3, 2), sixteenths(4, -1), sixteenths(-5, -2), sixteenths(2, 5),
    sixteenths(5, 3),  sixteenths(3, -5),  sixteenths(-2, 6), sixteenths(0, -7), sixteenths(-4, -6), sixteenths(-6, 4),
    sixteenths(-8, 0), sixteenths(7, -4),  sixteenths(6, 7),  sixteenths(-7, -8)};

}  // namespace

std::span<const glm::vec2> sample_offsets(int samples) {
    switch (samples) {
    case 1: return kOne;
    case 2: return kTwo;
    case 4: return kFour;
    case 8: return kEight;
    case 16: return kSixteen;
    default: throw std::invalid_argument("samples per pixel must be 1, 2, 4, 8 or 16, got " + std::to_string(samples));
    }
}

}  // namespace raster
