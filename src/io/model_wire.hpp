#pragma once

#include <raster/io/model.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

// A Model as bytes, for the trip from the reader process to the one that draws it. The reader
// trusts nothing: every count is checked against the bytes that remain.
namespace raster::detail {

// About how many bytes append_model_wire writes for `model`: enough to reserve them at once.
[[nodiscard]] std::size_t model_wire_size(const Model& model) noexcept;

// Appends `model` to `out`; textures shared by parts are written once.
void append_model_wire(const Model& model, std::vector<std::uint8_t>& out);

// The model written by append_model_wire; throws std::runtime_error for bytes it did not write.
[[nodiscard]] Model model_from_wire(std::span<const std::uint8_t> bytes);

}  // namespace raster::detail
