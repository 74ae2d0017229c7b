#pragma once

#include "io/wire_bytes.hpp"

#include <raster/io/model.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

// A Model as bytes, for the trip from the reader process to the one that draws it. The reader
// trusts nothing: every count is checked against the bytes that remain.
namespace raster::detail {

// Exactly how many bytes write_model_wire writes for `model`, counted without copying an array.
[[nodiscard]] std::size_t model_wire_bytes(const Model& model);

// Writes `model` (into a span model_wire_bytes long, say); textures shared by parts are written once.
void write_model_wire(const Model& model, WireWriter& wire);

// Appends `model` to `out`.
void append_model_wire(const Model& model, std::vector<std::uint8_t>& out);

// The model written by append_model_wire; throws std::runtime_error for bytes it did not write.
[[nodiscard]] Model model_from_wire(std::span<const std::uint8_t> bytes);

}  // namespace raster::detail
