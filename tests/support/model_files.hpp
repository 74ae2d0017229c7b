#pragma once

#include <raster/image/framebuffer.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

// Image and model files the tests write themselves, byte by byte, so that no test depends on a
// file it did not make.
namespace test_support {

// 24-bit uncompressed BMP, bottom-up rows as the format stores them.
void write_bmp(const std::filesystem::path& path, const raster::Framebuffer& image);
// Uncompressed true-colour TGA with its origin at the top left.
void write_tga(const std::filesystem::path& path, const raster::Framebuffer& image);
// RGB PNG whose pixels sit in stored (uncompressed) deflate blocks.
void write_png(const std::filesystem::path& path, const raster::Framebuffer& image);

// A checkerboard of `squares` x `squares` squares of `texels` texels each, in two colours.
raster::Framebuffer checkerboard(int squares, int texels, raster::Rgb a, raster::Rgb b);

// A unit cube (corners at +-1) whose six faces each map the whole texture, counter-clockwise
// from outside as OBJ files have them, with `mtllib` and `usemtl` lines when given.
std::string textured_cube_obj(const std::string& mtllib, const std::string& material);

// Writes crate.obj, crate.mtl and checker.png into `folder`: a checkered cube (material
// "crate", its map a 4 x 4 checkerboard of 8-texel squares) standing on a plain floor
// (material "floor", Kd only); returns the OBJ's path.
std::filesystem::path write_crate_on_floor(const std::filesystem::path& folder);

// A glTF 2.0 file with its buffer embedded (base64): one square mesh drawn by two nodes under a
// parent, the second turned 45 degrees about z, halved and moved right; base colour
// (0.8, 0.2, 0.1), metallic 0, roughness 0.5.
std::string gltf_two_squares();
// A glTF 2.0 triangle whose three corners have the linear COLOR_0 `colour`, no material.
std::string gltf_coloured_triangle(float red, float green, float blue);
// A tetrahedron with one corner at the origin, as ASCII and as binary STL (the same facets);
// the binary one's facets carry `attributes`, where bit 15 marks a colour of 5-bit channels,
// red in bits 10-14 (VisCAM and SolidView's convention).
std::string stl_tetrahedron_ascii();
std::string stl_tetrahedron_binary(std::array<std::uint16_t, 4> attributes = {});
// A square pyramid in ASCII PLY: four triangles and a quad base, with per-vertex colours.
std::string ply_pyramid();

}  // namespace test_support
