#pragma once

#include <raster/geometry/cube.hpp>
#include <raster/image/framebuffer.hpp>

#include <array>

namespace raster {

inline constexpr Rgb kBlack{0, 0, 0};
inline constexpr Rgb kWhite{255, 255, 255};
inline constexpr Rgb kCornflowerBlue{100, 149, 237};

// One flat colour per face slot (FaceSlot); near and far are blue and red so they cannot be
// mistaken for each other.
inline constexpr std::array<Rgb, 6> kCubeFacePalette{{
    {0, 0, 255},      // kNearFace (-Z): deep blue
    {255, 0, 0},      // kFarFace (+Z): red
    {237, 190, 77},   // kRightFace (+X): amber
    {155, 102, 210},  // kLeftFace (-X): iris
    {78, 198, 128},   // kTopFace (+Y): jade
    {234, 128, 196},  // kBottomFace (-Y): orchid
}};

}  // namespace raster
