#pragma once

#include <raster/geometry/mesh.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

// The models of raster-engine's world, each built from boxes, pyramids, quads and octagonal
// prisms (primitives.hpp) in its own frame: base on y = 0, front toward +Z, metres.
namespace raster::detail {

// A placement: moved to `where` and turned by `yaw` radians about +Y.
[[nodiscard]] glm::mat4 placed_at(glm::vec3 where, float yaw = 0.0F);

// An aeroplane's body, wings and tail in one livery; its nose at z = +4.4, the propeller hub
// at kPropellerHub. Lies on its wheels at y = 0.
[[nodiscard]] Mesh aeroplane();
inline constexpr glm::vec3 kPropellerHub{0.0F, 1.55F, 4.55F};
// Two blades and a hub across the Z axis through the origin; the scene turns them about it.
[[nodiscard]] Mesh propeller();

// Tree trunks, needles and leaves, in separate meshes because they take different textures.
struct TreeParts {
    Mesh trunks;
    Mesh needles;
    Mesh leaves;
};
// A fir: stacked pyramids on a short trunk.
void add_fir(TreeParts& trees, glm::vec3 where, float height);
// A broad-leaved tree: a boxy crown on a trunk.
void add_oak(TreeParts& trees, glm::vec3 where, float height);
// A palm: a tall leaning trunk with drooping fronds.
void add_palm(TreeParts& trees, glm::vec3 where, float yaw);

}  // namespace raster::detail
