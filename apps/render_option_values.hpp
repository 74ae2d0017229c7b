#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <CLI/CLI.hpp>
#include <glm/vec3.hpp>

// The values render's options take beyond numbers and names: points, colours, sizes, models.

// --eye 1,2,3 and the like: one word of three numbers separated by commas, so that the option
// takes exactly one argument wherever it stands and "-3,-3,-3" is a value, not an option.
void add_point_option(CLI::App& app, const std::string& name, std::optional<glm::dvec3>& point,
                      const std::string& help);
// --background #RRGGBB: six hexadecimal digits, the # optional; or none.
[[nodiscard]] bool is_hex_colour(const std::string& text);
raster::Rgb colour_from_hex(const std::string& text);
// Bytes from "512M", "2G", "2.5GiB", "1048576" (K, M, G, T are powers of 1024); nothing for other text.
[[nodiscard]] std::optional<std::uint64_t> memory_size(const std::string& text);
// A name ending in a model's extension (.obj, .gltf, .glb, .stl, .ply), in any case.
[[nodiscard]] bool looks_like_a_model(const std::string& name);
