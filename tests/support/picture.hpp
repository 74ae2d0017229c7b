#pragma once

#include <raster/image/framebuffer.hpp>

#include <map>
#include <string>
#include <vector>
#include <gtest/gtest.h>

// Pixel tests as pictures: one character per pixel, one string per row.
namespace test_support {

// Black is '.', any colour missing from the legend is '+'.
std::string to_ascii_art(const raster::Framebuffer& image, const std::map<char, raster::Rgb>& legend = {});

// Passes when the image reads as `rows`; on failure prints both pictures side by side.
::testing::AssertionResult looks_like(const raster::Framebuffer& image, const std::vector<std::string>& rows,
                                      const std::map<char, raster::Rgb>& legend = {});

}  // namespace test_support
