#pragma once

#include <raster/geometry/model.hpp>
#include <raster/io/reader_limits.hpp>

#include <functional>
#include <string>

// A model read in a child process under limits, so that a reader we do not own (assimp,
// tinyobjloader, stb_image) can crash, loop or allocate without end and take only itself down.
namespace raster::detail {

// Runs `read` in a forked child with its address space, processor time and file writes
// limited, and takes its model back through a pipe; in this process when the limits say so.
// Throws std::runtime_error with one line naming `name` when the child crashed ("the
// `reader` reader crashed"), ran out of memory or time, or `read` threw.
[[nodiscard]] Model read_in_child(const std::function<Model()>& read, const std::string& name, const std::string& reader,
                                  const ReaderLimits& limits);

}  // namespace raster::detail
