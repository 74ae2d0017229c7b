#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>
#include <raster/platform/stopwatch.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

// Models of every format `render` reads, chosen by the file name's ending
// (doc/conventions.md#models).
namespace raster {

// glTF 2.0 (.gltf with its buffers and images, .glb), STL and PLY through the Open Asset Import
// Library: every node's meshes placed by the node's matrices, base colour and its texture (sRGB)
// as the diffuse colour and map, metallic-roughness as a Phong highlight, normals and texture
// coordinates where the file has them. Every file it opens goes through InputFile. Throws
// std::runtime_error with one line naming the file for a file it cannot use.
[[nodiscard]] Model read_scene_file(const std::filesystem::path& path, const ObjOptions& options = {});

// The same from bytes in memory, `format` naming the kind ("gltf", "glb", "stl", "ply"); no other
// file is opened and no map loaded. For tests and fuzzing.
[[nodiscard]] Model parse_scene_file(std::span<const std::uint8_t> bytes, const std::string& format,
                                     const ObjOptions& options = {});

// read_obj for .obj (any letter case), read_ply for .ply, read_stl for .stl, read_scene_file for .gltf, .glb and the
// further formats of model_endings(); a format raster knows but does not read is refused saying
// why, any other ending with the list of those it reads, and a file whose first bytes are
// another format's saying what it looks like (doc/conventions.md#model-formats). PLY and STL are read in this process
// (raster's own readers, their counts checked against options.limits' memory first), the others in a
// child process under options.limits: a crash, a timeout or memory running out is one line naming the file.
// `spent`, when given, receives the read's wall time and processor time: the child's and this
// thread's (the copy back), or the whole process's where the read runs in it.
[[nodiscard]] Model read_model(const std::filesystem::path& path, const ObjOptions& options = {},
                               Spent* spent = nullptr);

// ".obj, .gltf, .glb, ... or .zgl": every ending read_model takes.
[[nodiscard]] std::string model_endings();
// Whether read_model takes a file of this name's ending (any letter case).
[[nodiscard]] bool has_model_ending(const std::filesystem::path& path);

}  // namespace raster
