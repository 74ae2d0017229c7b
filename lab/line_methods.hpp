#pragma once

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <span>
#include <string_view>
#include <glm/vec2.hpp>

// Every line method we measure, behind one signature.
namespace lab {

struct LineMethod {
    std::string_view id;
    std::string_view label;
    // Draws from pixel `from` to pixel `to` into a framebuffer whose top-left pixel is at
    // `origin`; returns the samples it stepped through.
    std::int64_t (*draw)(raster::Framebuffer& target, glm::ivec2 origin, glm::ivec2 from, glm::ivec2 to);
    bool is_product;
};

[[nodiscard]] std::span<const LineMethod> line_methods();
[[nodiscard]] const LineMethod& product_line();

}  // namespace lab
