#pragma once

#include <raster/io/model.hpp>
#include <raster/io/reader_limits.hpp>
#include <raster/io/texture_file.hpp>

#include <cstdint>
#include <filesystem>
#include <string_view>

// Wavefront OBJ models with their MTL materials and diffuse maps (doc/conventions.md#models).
namespace raster {

// The largest OBJ or MTL file read, in bytes.
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{1} << 30;
// The longest line of an OBJ or MTL file, in bytes: one line is held whole while it is read.
inline constexpr std::size_t kMaxObjLineBytes = std::size_t{4} << 20;
// The most corners one face may have: splitting a polygon takes time quadratic in its corners.
inline constexpr std::size_t kMaxFaceCorners = 1024;
// The most texels all of one model's textures may hold together: four of the largest.
inline constexpr std::size_t kMaxModelTexels = 4 * kMaxTextureTexels;

struct ObjOptions {
    // Normals the file lacks are made per corner: facets meeting at less than this angle are
    // smoothed together, sharper edges stay creased (0: every facet flat).
    double crease_degrees = 60.0;
    bool load_textures = true;
    std::size_t max_texels = kMaxTextureTexels;
    std::size_t max_line_bytes = kMaxObjLineBytes;  // the fuzzer lowers it to reach the refusal
    // Threads a reader may use (0: available_cores()): an OBJ is read in byte ranges at once,
    // each at least `range_bytes` long (tests and the fuzzer lower it to split small files).
    std::size_t threads = 0;
    std::size_t range_bytes = std::size_t{1} << 20;
    // When set (by confinement_root), nothing outside this directory is read: what the model
    // names there is missing, with a warning.
    std::filesystem::path confine{};
    // What read_model lets one model's reading cost (in a process of its own for readers not raster's).
    ReaderLimits limits{};
};

// Reads an OBJ file, the MTL files it names (beside it) and their diffuse maps (relative to the
// MTL file). Throws std::runtime_error with one line naming the file (and the line, as
// "file:12: ...", where known) for a file it cannot use; problems it can work around become the
// model's warnings.
[[nodiscard]] Model read_obj(const std::filesystem::path& path, const ObjOptions& options = {});

// The same from text in memory, `mtl` standing for every material library the OBJ names; maps
// are not loaded. For tests and fuzzing.
[[nodiscard]] Model parse_obj(std::string_view obj, std::string_view mtl, ObjOptions options = {});

}  // namespace raster
