#include "scenes/island_parts.hpp"

#include <raster/geometry/primitives.hpp>

#include <numbers>
#include <glm/gtc/matrix_transform.hpp>

namespace raster::detail {

namespace {

constexpr float kQuarterTurn = std::numbers::pi_v<float> / 2.0F;

glm::mat4 moved(glm::vec3 where) { return glm::translate(glm::mat4(1.0F), where); }

}  // namespace

glm::mat4 placed_at(glm::vec3 where, float yaw) { return glm::rotate(moved(where), yaw, glm::vec3(0, 1, 0)); }

Mesh aeroplane() {
    Mesh plane;
    // The fuselage, an octagonal prism along Z, and its nose cone, a pyramid turned to face +Z.
    append_posed(plane, textured_prism(8, 0.8F, 7.0F, 2.0F), moved({0, 1.55F, 0}));
    append_posed(plane, textured_pyramid(1.6F, 1.6F, 0.9F, 2.0F),
                 glm::rotate(moved({0, 1.55F, 3.5F}), kQuarterTurn, glm::vec3(1, 0, 0)));
    append_posed(plane, textured_pyramid(1.6F, 1.6F, 1.6F, 2.0F),
                 glm::rotate(moved({0, 1.55F, -3.5F}), -kQuarterTurn, glm::vec3(1, 0, 0)));
    append_posed(plane, textured_box({11.0F, 0.18F, 1.8F}, 2.0F), moved({0, 1.35F, 0.9F}));
    append_posed(plane, textured_box({3.8F, 0.14F, 0.9F}, 2.0F), moved({0, 1.9F, -4.0F}));
    append_posed(plane, textured_box({0.14F, 1.5F, 1.1F}, 2.0F), moved({0, 2.7F, -4.0F}));
    append_posed(plane, textured_box({0.9F, 0.5F, 1.3F}, 1.0F), moved({0, 2.4F, 1.1F}));  // the cockpit canopy
    // The undercarriage: two wheels under the wings on struts, one under the tail.
    for (const float side : {-1.3F, 1.3F}) {
        append_posed(plane, textured_box({0.12F, 0.8F, 0.12F}, 1.0F), moved({side, 0.75F, 1.2F}));
        append_posed(plane, textured_prism(8, 0.35F, 0.2F, 1.0F),
                     glm::rotate(moved({side, 0.35F, 1.2F}), kQuarterTurn, glm::vec3(0, 1, 0)));
    }
    append_posed(plane, textured_prism(8, 0.18F, 0.12F, 1.0F),
                 glm::rotate(moved({0, 0.5F, -3.3F}), kQuarterTurn, glm::vec3(0, 1, 0)));
    return plane;
}

Mesh propeller() {
    Mesh blades;
    append_posed(blades, textured_box({0.26F, 3.0F, 0.06F}, 1.0F), glm::mat4(1.0F));
    append_posed(blades, textured_prism(8, 0.2F, 0.3F, 1.0F), glm::mat4(1.0F));
    return blades;
}

void add_fir(TreeParts& trees, glm::vec3 where, float height) {
    const float k = height / 6.0F;
    append_posed(trees.trunks, textured_box({0.4F * k, 1.4F * k, 0.4F * k}, 1.0F),
                 moved(where + glm::vec3(0, 0.7F * k, 0)));
    append_posed(trees.needles, textured_pyramid(3.2F * k, 3.2F * k, 2.6F * k, 1.5F),
                 placed_at(where + glm::vec3(0, 1.0F * k, 0), 0.3F));
    append_posed(trees.needles, textured_pyramid(2.4F * k, 2.4F * k, 2.4F * k, 1.5F),
                 placed_at(where + glm::vec3(0, 2.6F * k, 0), 0.9F));
    append_posed(trees.needles, textured_pyramid(1.5F * k, 1.5F * k, 2.0F * k, 1.5F),
                 placed_at(where + glm::vec3(0, 4.0F * k, 0), 0.1F));
}

void add_oak(TreeParts& trees, glm::vec3 where, float height) {
    const float k = height / 5.0F;
    append_posed(trees.trunks, textured_box({0.5F * k, 2.2F * k, 0.5F * k}, 1.0F),
                 moved(where + glm::vec3(0, 1.1F * k, 0)));
    append_posed(trees.leaves, textured_box({3.0F * k, 2.2F * k, 3.0F * k}, 1.5F),
                 placed_at(where + glm::vec3(0, 3.2F * k, 0), 0.4F));
    append_posed(trees.leaves, textured_box({2.0F * k, 1.0F * k, 2.0F * k}, 1.5F),
                 placed_at(where + glm::vec3(0, 4.6F * k, 0), 1.1F));
}

void add_palm(TreeParts& trees, glm::vec3 where, float yaw) {
    // The trunk leans 0.2 rad, as palms do; the fronds sit on its tip.
    const glm::mat4 lean = glm::rotate(placed_at(where, yaw), 0.2F, glm::vec3(1, 0, 0));
    append_posed(trees.trunks, textured_box({0.35F, 5.0F, 0.35F}, 1.0F), lean * moved({0, 2.5F, 0}));
    for (int k = 0; k < 5; ++k) {
        const glm::mat4 frond =
            glm::rotate(glm::rotate(lean * moved({0, 5.0F, 0}), static_cast<float>(k) * 1.2566F, glm::vec3(0, 1, 0)),
                        0.35F, glm::vec3(1, 0, 0));  // the tip droops
        append_posed(trees.leaves, textured_box({0.7F, 0.08F, 2.6F}, 1.0F), frond * moved({0, 0, 1.3F}));
    }
}

}  // namespace raster::detail
