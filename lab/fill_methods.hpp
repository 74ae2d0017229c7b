#pragma once

#include "coverage.hpp"

#include <span>
#include <string_view>
#include <glm/vec2.hpp>

// Every convex-polygon fill we measure, behind one signature so each sees identical input.
namespace lab {

struct FillMethod {
    std::string_view id;     // CSV key
    std::string_view label;  // chart label
    // Corners in pixel coordinates (pixel centres on whole numbers); hits covered pixels.
    void (*fill)(std::span<const glm::dvec2> corners, Coverage& target);
    bool is_product;
};

[[nodiscard]] std::span<const FillMethod> fill_methods();
[[nodiscard]] const FillMethod& product_fill();

}  // namespace lab
