#pragma once

#include <raster/image/framebuffer.hpp>

#include <string>
#include <vector>
#include <gtest/gtest.h>

// Golden images in snapshots/, compared by decoded pixels. With RASTER_UPDATE_SNAPSHOTS=1 in
// the environment the comparisons write the snapshots instead (`--target update-snapshots`).
namespace test_support {

// Compares with snapshots/<name>.webp; on mismatch names the differing pixel count and the
// first difference, and writes <name>.actual.webp and <name>.diff.webp under the build tree.
::testing::AssertionResult matches_snapshot(const raster::Framebuffer& actual, const std::string& name);

// Compares one digest per line with snapshots/<name>.digests.
::testing::AssertionResult matches_digests(const std::vector<std::string>& digests, const std::string& name);

// A 64-bit FNV-1a digest of the size and pixels, as 16 hex digits.
std::string digest_of(const raster::Framebuffer& image);

}  // namespace test_support
